// The claims of an LTI 1.3 launch, checked.
#include "serve/lti.h"

#include <algorithm>

#include "serve/jwt.h"

namespace raygrade::serve {

namespace {

[[noreturn]] void refuse(const std::string& why) { throw Refusal(401, why); }

std::string claim_name(std::string_view prefix, std::string_view name) {
  return std::string(prefix) + std::string(name);
}

// A string claim that must be there and not be empty.
std::string required_string(const nlohmann::json& p, const std::string& name) {
  auto it = p.find(name);
  if (it == p.end() || !it->is_string() || it->get<std::string>().empty())
    refuse("the id_token has no " + name + " claim (or it is not a string)");
  return it->get<std::string>();
}

std::string optional_string(const nlohmann::json& o, const std::string& name) {
  auto it = o.find(name);
  return it != o.end() && it->is_string() ? it->get<std::string>() : std::string();
}

std::int64_t required_time(const nlohmann::json& p, const std::string& name) {
  auto it = p.find(name);
  if (it == p.end() || !it->is_number()) refuse("the id_token has no numeric " + name + " claim");
  return static_cast<std::int64_t>(it->get<double>());
}

// iss, aud, azp, exp, iat and nonce: the OpenID Connect checks of the Security Framework.
void check_identity_claims(const nlohmann::json& p, const LaunchExpectation& expect) {
  if (required_string(p, "iss") != expect.issuer)
    refuse("the id_token's issuer is not the platform that started this login");
  auto aud = p.find("aud");
  std::vector<std::string> audiences;
  if (aud != p.end() && aud->is_string()) audiences.push_back(aud->get<std::string>());
  if (aud != p.end() && aud->is_array()) {
    for (const auto& a : *aud)
      if (a.is_string()) audiences.push_back(a.get<std::string>());
  }
  if (std::find(audiences.begin(), audiences.end(), expect.client_id) == audiences.end())
    refuse("the id_token's audience does not hold this tool's client_id");
  auto azp = p.find("azp");
  if (audiences.size() > 1 && azp == p.end())
    refuse("the id_token has several audiences and no azp claim");
  if (azp != p.end() && (!azp->is_string() || azp->get<std::string>() != expect.client_id))
    refuse("the id_token's azp is not this tool's client_id");
  if (required_time(p, "exp") + kClockSkew <= expect.now) refuse("the id_token has expired");
  if (required_time(p, "iat") > expect.now + kClockSkew)
    refuse("the id_token was issued in the future (iat)");
  if (expect.nonce.empty() || optional_string(p, "nonce") != expect.nonce)
    refuse("the id_token's nonce is not the one this tool issued for this login");
}

void read_resource_link(const nlohmann::json& p, LaunchClaims& c) {
  c.sub = required_string(p, "sub");
  auto link = p.find(claim_name(kClaimPrefix, "resource_link"));
  if (link == p.end() || !link->is_object() || optional_string(*link, "id").empty())
    refuse("the launch has no resource_link claim with an id");
  c.resource_link_id = (*link)["id"].get<std::string>();
  auto ags = p.find(std::string(kAgsClaim));
  if (ags != p.end() && ags->is_object()) {
    c.lineitem = optional_string(*ags, "lineitem");
    c.lineitems = optional_string(*ags, "lineitems");
  }
}

void read_deep_linking(const nlohmann::json& p, LaunchClaims& c) {
  c.sub = optional_string(p, "sub");
  auto settings = p.find(claim_name(kDlClaimPrefix, "deep_linking_settings"));
  if (settings == p.end() || !settings->is_object())
    refuse("the deep linking request has no deep_linking_settings claim");
  c.deep_link_return_url = optional_string(*settings, "deep_link_return_url");
  if (c.deep_link_return_url.empty())
    refuse("the deep linking request's settings have no deep_link_return_url");
  c.deep_link_data = optional_string(*settings, "data");
  // The tool returns resource links alone: a platform that takes none cannot be answered.
  auto accept = settings->find("accept_types");
  if (accept != settings->end() && accept->is_array() &&
      std::find(accept->begin(), accept->end(), "ltiResourceLink") == accept->end())
    refuse("the platform accepts no ltiResourceLink in this deep linking request");
}

}  // namespace

bool LaunchClaims::instructor() const {
  return std::any_of(roles.begin(), roles.end(), [](const std::string& r) {
    return r == kInstructorRole ||
           r == "http://purl.imsglobal.org/vocab/lis/v2/institution/person#Administrator" ||
           r == "http://purl.imsglobal.org/vocab/lis/v2/system/person#Administrator";
  });
}

LaunchClaims check_launch_claims(const nlohmann::json& p, const LaunchExpectation& expect) {
  check_identity_claims(p, expect);
  LaunchClaims c;
  c.deployment_id = required_string(p, claim_name(kClaimPrefix, "deployment_id"));
  if (std::find(expect.deployments.begin(), expect.deployments.end(), c.deployment_id) ==
      expect.deployments.end())
    refuse("the deployment '" + c.deployment_id + "' is not registered with this tool");
  c.message_type = required_string(p, claim_name(kClaimPrefix, "message_type"));
  if (c.message_type != kResourceLinkRequest && c.message_type != kDeepLinkingRequest)
    refuse("the message type '" + c.message_type + "' is not one this tool handles");
  if (required_string(p, claim_name(kClaimPrefix, "version")) != "1.3.0")
    refuse("the launch is not LTI version 1.3.0");
  auto roles = p.find(claim_name(kClaimPrefix, "roles"));
  if (roles == p.end() || !roles->is_array()) refuse("the launch has no roles claim (an array)");
  for (const auto& r : *roles)
    if (r.is_string()) c.roles.push_back(r.get<std::string>());
  if (c.message_type == kResourceLinkRequest) {
    c.target_link_uri = required_string(p, claim_name(kClaimPrefix, "target_link_uri"));
    read_resource_link(p, c);
  } else {
    read_deep_linking(p, c);
  }
  c.name = optional_string(p, "name");
  auto context = p.find(claim_name(kClaimPrefix, "context"));
  if (context != p.end() && context->is_object()) {
    c.context_id = optional_string(*context, "id");
    c.context_title = optional_string(*context, "title");
  }
  auto nrps = p.find(std::string(kNrpsClaim));
  if (nrps != p.end() && nrps->is_object())
    c.memberships_url = optional_string(*nrps, "context_memberships_url");
  auto custom = p.find(claim_name(kClaimPrefix, "custom"));
  if (custom != p.end() && custom->is_object()) c.custom = *custom;
  return c;
}

std::string student_key_of(const std::string& issuer, const std::string& sub) {
  return issuer + " " + sub;
}

}  // namespace raygrade::serve
