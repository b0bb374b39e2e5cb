// The claims of an LTI 1.3 launch (LTI Core 1.3, Deep Linking 2.0) checked as the Security
// Framework asks, against what the tool knows: the registration and the nonce it issued.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace raygrade::serve {

// The claims' names, as the specifications spell them.
inline constexpr std::string_view kClaimPrefix = "https://purl.imsglobal.org/spec/lti/claim/";
inline constexpr std::string_view kDlClaimPrefix = "https://purl.imsglobal.org/spec/lti-dl/claim/";
inline constexpr std::string_view kAgsClaim =
    "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint";
inline constexpr std::string_view kNrpsClaim =
    "https://purl.imsglobal.org/spec/lti-nrps/claim/namesroleservice";
inline constexpr std::string_view kResourceLinkRequest = "LtiResourceLinkRequest";
inline constexpr std::string_view kDeepLinkingRequest = "LtiDeepLinkingRequest";
inline constexpr std::string_view kInstructorRole =
    "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor";

// Seconds of difference between the platform's clock and ours taken as the same moment.
inline constexpr std::int64_t kClockSkew = 60;

// What the launch must match.
struct LaunchExpectation {
  std::string issuer;
  std::string client_id;
  std::vector<std::string> deployments;  // the deployment ids registered for them
  std::string nonce;                     // the one the tool issued with the state presented
  std::int64_t now = 0;                  // seconds since 1970 UTC
};

// A launch whose claims passed every check.
struct LaunchClaims {
  std::string message_type;
  std::string sub;
  std::string name;
  std::string deployment_id;
  std::vector<std::string> roles;
  std::string context_id;
  std::string context_title;
  std::string resource_link_id;
  std::string target_link_uri;
  nlohmann::json custom = nlohmann::json::object();
  std::string lineitem;   // AGS: the line item of the resource link, if any
  std::string lineitems;  // AGS: the context's line items, if given
  std::string deep_link_return_url;
  std::string deep_link_data;
  std::string memberships_url;  // NRPS: the context's roster, if given
  bool instructor() const;
};

// Every check of the claims (iss, aud, azp, exp, iat, nonce, deployment, message type, version
// and the claims each message requires). Throws Refusal (401) naming the first that fails.
LaunchClaims check_launch_claims(const nlohmann::json& payload, const LaunchExpectation& expect);

// The variant key of a platform's user: issuer and sub, one space between (an issuer is a URL,
// which has no space).
std::string student_key_of(const std::string& issuer, const std::string& sub);

}  // namespace raygrade::serve
