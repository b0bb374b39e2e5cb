// A course's class list read from the platform by Names and Role Provisioning Services 2.0: the
// membership container at the launch's context_memberships_url (the claim kNrpsClaim of
// lti.h), page after page.
#pragma once

#include <cstddef>
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
// The most bytes of one page: 32 MiB holds some 100,000 members of a few hundred bytes (a
// platform that does not page sends them all at once); a longer answer is not read.
inline constexpr std::size_t kMaxRosterPageBytes = std::size_t{32} << 20;
// The most members a roster keeps (read one at a time, never as a tree of the page): the
// largest courses; a roster longer than that is not read.
inline constexpr std::size_t kMaxRosterMembers = 100000;
// The most seconds a whole roster is read in (every page, each request cut at this time): an
// instructor's report waits no longer for a platform that hangs or sends a byte at a time.
inline constexpr int kRosterSeconds = 30;

// Every member of the container at `url`, read with the bearer `token`, following each page's
// Link rel="next" (NRPS 2.0, 2.4.1); in the platform's order, a user_id given twice kept once
// (the first; user_ids are compared byte for byte: they are opaque and case-sensitive), a
// member without a string user_id, or with a control character in it, left out (it names
// nobody a launch can name, and no database keeps it whole). A member without a status is
// Active. The token goes only to `url`'s origin: a next link elsewhere ends the read. Throws
// std::runtime_error saying why the roster could not be read (a next link to another
// origin, pages without end, a page longer than kMaxRosterPageBytes, more than
// kMaxRosterMembers members, more than kRosterSeconds in all).
std::vector<Member> read_memberships(const std::string& url, const std::string& token);

// The target of the Link header's rel="next" link ("" when there is none), a relative target
// resolved against `base` (the URL the header came with).
std::string next_link(const std::string& header, const std::string& base);

// A member whose roles hold the Learner role of a course (LIS v2 membership vocabulary, or its
// short name).
bool is_learner(const Member& m);

}  // namespace raygrade::serve
