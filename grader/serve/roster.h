// A course's class list read from the platform by Names and Role Provisioning Services 2.0: the
// membership container at the launch's context_memberships_url (the claim kNrpsClaim of
// lti.h), page after page.
#pragma once

#include <string>
#include <vector>

#include "serve/store.h"

namespace raygrade::serve {

inline constexpr std::string_view kNrpsScope =
    "https://purl.imsglobal.org/spec/lti-nrps/scope/contextmembership.readonly";
inline constexpr std::string_view kMembershipType =
    "application/vnd.ims.lti-nrps.v2.membershipcontainer+json";
// The most pages one roster is read in: a platform whose next links never end (or loop) is
// stopped there.
inline constexpr int kMaxRosterPages = 1000;

// Every member of the container at `url`, read with the bearer `token`, following each page's
// Link rel="next" (NRPS 2.0, 2.4.1); in the platform's order, a user_id given twice kept once
// (the first), a member without a user_id left out (it names nobody). A member without a
// status is Active. Throws std::runtime_error saying why the roster could not be read.
std::vector<Member> read_memberships(const std::string& url, const std::string& token);

// The target of the Link header's rel="next" link ("" when there is none), a relative target
// resolved against `base` (the URL the header came with).
std::string next_link(const std::string& header, const std::string& base);

// A member whose roles hold the Learner role of a course (LIS v2 membership vocabulary, or its
// short name).
bool is_learner(const Member& m);

}  // namespace raygrade::serve
