// The LTI tool's token checks: RS256 against the platform's keys, and the refusals the
// Security Framework 1.0 and LTI Core 1.3 ask for. Keys and tokens are made here with OpenSSL
// directly, not with the code under test.
#include <gtest/gtest.h>
#include <openssl/core_names.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/pem.h>

#include "serve/jwt.h"
#include "serve/lti.h"

namespace serve_jwt_test {

using nlohmann::json;
using raygrade::serve::PKey;
using raygrade::serve::Refusal;

// Base64url of RFC 4648 section 5, written from standard base64 by OpenSSL.
std::string b64url(const std::string& bytes) {
  std::string out(4 * ((bytes.size() + 2) / 3) + 1, '\0');
  int n = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()),
                          reinterpret_cast<const unsigned char*>(bytes.data()),
                          static_cast<int>(bytes.size()));
  out.resize(static_cast<std::size_t>(n));
  while (!out.empty() && out.back() == '=') out.pop_back();
  for (char& c : out) c = c == '+' ? '-' : c == '/' ? '_' : c;
  return out;
}

PKey new_key() { return PKey(EVP_RSA_gen(2048)); }

std::string bn_bytes(EVP_PKEY* key, const char* name) {
  BIGNUM* b = nullptr;
  EVP_PKEY_get_bn_param(key, name, &b);
  std::string out(static_cast<std::size_t>(BN_num_bytes(b)), '\0');
  BN_bn2bin(b, reinterpret_cast<unsigned char*>(out.data()));
  BN_free(b);
  return out;
}

json jwk_of(EVP_PKEY* key, const std::string& kid) {
  return {{"kty", "RSA"},
          {"kid", kid},
          {"n", b64url(bn_bytes(key, OSSL_PKEY_PARAM_RSA_N))},
          {"e", b64url(bn_bytes(key, OSSL_PKEY_PARAM_RSA_E))}};
}

std::string rs256(const std::string& input, EVP_PKEY* key) {
  EVP_MD_CTX* ctx = EVP_MD_CTX_new();
  std::size_t size = 0;
  EVP_DigestSignInit(ctx, nullptr, EVP_sha256(), nullptr, key);
  EVP_DigestSign(ctx, nullptr, &size, reinterpret_cast<const unsigned char*>(input.data()),
                 input.size());
  std::string sig(size, '\0');
  EVP_DigestSign(ctx, reinterpret_cast<unsigned char*>(sig.data()), &size,
                 reinterpret_cast<const unsigned char*>(input.data()), input.size());
  EVP_MD_CTX_free(ctx);
  sig.resize(size);
  return sig;
}

std::string token(const json& header, const json& payload, EVP_PKEY* key) {
  std::string input = b64url(header.dump()) + "." + b64url(payload.dump());
  return input + "." + b64url(key ? rs256(input, key) : "");
}

std::string public_pem(EVP_PKEY* key) {
  BIO* bio = BIO_new(BIO_s_mem());
  PEM_write_bio_PUBKEY(bio, key);
  char* data = nullptr;
  long n = BIO_get_mem_data(bio, &data);
  std::string out(data, static_cast<std::size_t>(n));
  BIO_free(bio);
  return out;
}

// The platform: one key, kid "p1".
struct Platform {
  PKey key = new_key();
  json jwk = jwk_of(key.get(), "p1");
  raygrade::serve::KeyLookup lookup() const {
    return [this](const std::string& kid) {
      return kid == "p1" ? raygrade::serve::rsa_public_key_from_jwk(jwk) : PKey();
    };
  }
};

int refusal_status(const std::string& t, const raygrade::serve::KeyLookup& keys) {
  try {
    raygrade::serve::verify_platform_jwt(t, keys);
  } catch (const Refusal& r) {
    return r.status();
  }
  return 200;
}

const json kHeader = {{"alg", "RS256"}, {"typ", "JWT"}, {"kid", "p1"}};
const json kPayload = {{"iss", "https://lms.example"}, {"sub", "s1"}};

TEST(Base64Url, Rfc4648Vectors) {
  using raygrade::serve::base64url_decode;
  using raygrade::serve::base64url_encode;
  // RFC 4648 section 10, without padding; "\xfb\xff" is "+/8" in base64, "-_8" in base64url.
  const std::pair<std::string, std::string> vectors[] = {
      {"", ""},           {"f", "Zg"},          {"fo", "Zm8"},          {"foo", "Zm9v"},
      {"foob", "Zm9vYg"}, {"fooba", "Zm9vYmE"}, {"foobar", "Zm9vYmFy"}, {"\xfb\xff", "-_8"}};
  for (const auto& [bytes, text] : vectors) {
    EXPECT_EQ(base64url_encode(bytes), text);
    EXPECT_EQ(base64url_decode(text), bytes);
  }
  EXPECT_FALSE(base64url_decode("Zm9v+"));  // '+' is standard base64's, not base64url's
  EXPECT_FALSE(base64url_decode("Z"));      // six bits make no byte
}

TEST(PlatformJwt, SignedWithTheRegisteredKeyIsAccepted) {
  Platform p;
  auto jwt =
      raygrade::serve::verify_platform_jwt(token(kHeader, kPayload, p.key.get()), p.lookup());
  EXPECT_EQ(jwt.payload["sub"], "s1");
}

TEST(PlatformJwt, AnotherKeysSignatureIsRefused) {
  Platform p;
  PKey other = new_key();
  EXPECT_EQ(refusal_status(token(kHeader, kPayload, other.get()), p.lookup()), 401);
}

TEST(PlatformJwt, AlteredPayloadIsRefused) {
  Platform p;
  std::string t = token(kHeader, kPayload, p.key.get());
  std::size_t dot = t.find('.');
  std::string forged = t.substr(0, dot + 1) +
                       b64url(json{{"iss", "https://lms.example"}, {"sub", "s2"}}.dump()) +
                       t.substr(t.rfind('.'));
  EXPECT_EQ(refusal_status(forged, p.lookup()), 401);
}

TEST(PlatformJwt, AlgNoneIsRefused) {
  Platform p;
  json h = {{"alg", "none"}, {"kid", "p1"}};
  EXPECT_EQ(refusal_status(token(h, kPayload, nullptr), p.lookup()), 401);
}

TEST(PlatformJwt, Hs256KeyedWithThePublicKeyIsRefused) {
  Platform p;
  json h = {{"alg", "HS256"}, {"kid", "p1"}};
  std::string input = b64url(h.dump()) + "." + b64url(kPayload.dump());
  std::string secret = public_pem(p.key.get());
  unsigned char mac[EVP_MAX_MD_SIZE];
  unsigned int len = 0;
  HMAC(EVP_sha256(), secret.data(), static_cast<int>(secret.size()),
       reinterpret_cast<const unsigned char*>(input.data()), input.size(), mac, &len);
  std::string t = input + "." + b64url(std::string(reinterpret_cast<char*>(mac), len));
  EXPECT_EQ(refusal_status(t, p.lookup()), 401);
}

TEST(PlatformJwt, UnknownKidIsRefused) {
  Platform p;
  json h = kHeader;
  h["kid"] = "p2";
  EXPECT_EQ(refusal_status(token(h, kPayload, p.key.get()), p.lookup()), 401);
  h.erase("kid");
  EXPECT_EQ(refusal_status(token(h, kPayload, p.key.get()), p.lookup()), 401);
}

TEST(PlatformJwt, KeyNamedInTheHeaderIsRefusedEvenWhenTheSignatureHolds) {
  Platform p;
  PKey attacker = new_key();
  for (const char* named : {"jwk", "jku", "x5u", "x5c"}) {
    json h = kHeader;
    h[named] = std::string(named) == "jwk" ? jwk_of(attacker.get(), "p1")
                                           : json("https://attacker.example/keys");
    // Signed with the registered key: still refused, since the header points elsewhere.
    EXPECT_EQ(refusal_status(token(h, kPayload, p.key.get()), p.lookup()), 401) << named;
    EXPECT_EQ(refusal_status(token(h, kPayload, attacker.get()), p.lookup()), 401) << named;
  }
}

TEST(PlatformJwt, NotThreePartsIsABadRequest) {
  Platform p;
  EXPECT_EQ(refusal_status("abc.def", p.lookup()), 400);
  EXPECT_EQ(refusal_status("a.b.c.d", p.lookup()), 400);
}

TEST(ToolJwt, SignatureVerifiesWithOpenSsl) {
  std::string pem = raygrade::serve::generate_rsa_pem();
  PKey key = raygrade::serve::private_key_from_pem(pem);
  ASSERT_TRUE(key);
  std::string t = raygrade::serve::sign_jwt(json{{"iss", "tool"}}, key.get(), "k1");
  std::size_t last = t.rfind('.');
  // The public half published as a JWK, read back by the test's own reading of n and e.
  json published = raygrade::serve::public_jwk(key.get(), "k1");
  EXPECT_EQ(published["n"], b64url(bn_bytes(key.get(), OSSL_PKEY_PARAM_RSA_N)));
  EXPECT_EQ(published["alg"], "RS256");
  EXPECT_EQ(published["use"], "sig");
  std::string input = t.substr(0, last);
  std::string sig = *raygrade::serve::base64url_decode(t.substr(last + 1));
  EVP_MD_CTX* ctx = EVP_MD_CTX_new();
  EVP_DigestVerifyInit(ctx, nullptr, EVP_sha256(), nullptr, key.get());
  int verdict =
      EVP_DigestVerify(ctx, reinterpret_cast<const unsigned char*>(sig.data()), sig.size(),
                       reinterpret_cast<const unsigned char*>(input.data()), input.size());
  EVP_MD_CTX_free(ctx);
  EXPECT_EQ(verdict, 1);
  auto header = json::parse(*raygrade::serve::base64url_decode(t.substr(0, t.find('.'))));
  EXPECT_EQ(header["kid"], "k1");
  EXPECT_EQ(header["alg"], "RS256");
}

// --- Claims (LTI Core 1.3 section 5.3 and 5.4, Security Framework 5.1.3)

constexpr std::int64_t kNow = 1'800'000'000;
const std::string kIss = "https://lms.example";
const std::string kClaim = "https://purl.imsglobal.org/spec/lti/claim/";

raygrade::serve::LaunchExpectation expectation() {
  return {kIss, "tool-1", {"dep-1"}, "nonce-1", kNow};
}

json resource_link() {
  return {{"iss", kIss},
          {"aud", "tool-1"},
          {"sub", "student-7"},
          {"exp", kNow + 300},
          {"iat", kNow},
          {"nonce", "nonce-1"},
          {kClaim + "deployment_id", "dep-1"},
          {kClaim + "message_type", "LtiResourceLinkRequest"},
          {kClaim + "version", "1.3.0"},
          {kClaim + "roles", {"http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"}},
          {kClaim + "resource_link", {{"id", "rl-1"}}},
          {kClaim + "target_link_uri", "https://tool.example/lti/launch"}};
}

// 200 when the claims pass, else the refusal's status.
int claims_status(const json& payload,
                  const raygrade::serve::LaunchExpectation& e = expectation()) {
  try {
    raygrade::serve::check_launch_claims(payload, e);
  } catch (const Refusal& r) {
    return r.status();
  }
  return 200;
}

TEST(LaunchClaims, ResourceLinkIsAccepted) {
  auto c = raygrade::serve::check_launch_claims(resource_link(), expectation());
  EXPECT_EQ(c.sub, "student-7");
  EXPECT_EQ(c.resource_link_id, "rl-1");
  EXPECT_FALSE(c.instructor());
}

TEST(LaunchClaims, IssuerMustBeThePlatformOfTheLogin) {
  json p = resource_link();
  p["iss"] = "https://other.example";
  EXPECT_EQ(claims_status(p), 401);
}

TEST(LaunchClaims, AudienceMustHoldTheClientId) {
  json p = resource_link();
  p["aud"] = "tool-2";
  EXPECT_EQ(claims_status(p), 401);
  p["aud"] = json::array({"tool-2", "tool-3"});
  p["azp"] = "tool-2";
  EXPECT_EQ(claims_status(p), 401);
}

TEST(LaunchClaims, SeveralAudiencesNeedAzpEqualToTheClientId) {
  json p = resource_link();
  p["aud"] = json::array({"tool-1", "tool-2"});
  EXPECT_EQ(claims_status(p), 401);  // no azp
  p["azp"] = "tool-2";
  EXPECT_EQ(claims_status(p), 401);
  p["azp"] = "tool-1";
  EXPECT_EQ(claims_status(p), 200);
}

TEST(LaunchClaims, ExpiryAllowsSixtySecondsOfSkewAndNoMore) {
  json p = resource_link();
  p["exp"] = kNow - 30;
  EXPECT_EQ(claims_status(p), 200);
  p["exp"] = kNow - 61;
  EXPECT_EQ(claims_status(p), 401);
  p.erase("exp");
  EXPECT_EQ(claims_status(p), 401);
}

TEST(LaunchClaims, IssuedInTheFutureBeyondTheSkewIsRefused) {
  json p = resource_link();
  p["iat"] = kNow + 30;
  EXPECT_EQ(claims_status(p), 200);
  p["iat"] = kNow + 120;
  EXPECT_EQ(claims_status(p), 401);
}

TEST(LaunchClaims, NonceMustBeTheOneIssuedForThisLogin) {
  json p = resource_link();
  p["nonce"] = "nonce-2";
  EXPECT_EQ(claims_status(p), 401);
  p.erase("nonce");
  EXPECT_EQ(claims_status(p), 401);
  auto e = expectation();
  e.nonce = "";  // a state with no nonce matches no token, not one without a nonce
  EXPECT_EQ(claims_status(p, e), 401);
}

TEST(LaunchClaims, DeploymentMustBeRegistered) {
  json p = resource_link();
  p[kClaim + "deployment_id"] = "dep-9";
  EXPECT_EQ(claims_status(p), 401);
}

TEST(LaunchClaims, MessageTypeAndVersionAreChecked) {
  json p = resource_link();
  p[kClaim + "message_type"] = "LtiSubmissionReviewRequest";
  EXPECT_EQ(claims_status(p), 401);
  p = resource_link();
  p[kClaim + "version"] = "1.1";
  EXPECT_EQ(claims_status(p), 401);
}

TEST(LaunchClaims, RequiredClaimsOfAResourceLink) {
  for (const std::string& missing : {std::string("sub"), kClaim + "roles", kClaim + "resource_link",
                                     kClaim + "target_link_uri", kClaim + "deployment_id"}) {
    json p = resource_link();
    p.erase(missing);
    EXPECT_EQ(claims_status(p), 401) << missing;
  }
  json p = resource_link();
  p[kClaim + "resource_link"] = json::object();
  EXPECT_EQ(claims_status(p), 401);
}

TEST(LaunchClaims, DeepLinkingNeedsItsSettings) {
  json p = resource_link();
  p[kClaim + "message_type"] = "LtiDeepLinkingRequest";
  p.erase(kClaim + "resource_link");
  p[kClaim + "roles"] = {"http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"};
  EXPECT_EQ(claims_status(p), 401);
  p["https://purl.imsglobal.org/spec/lti-dl/claim/deep_linking_settings"] = {
      {"deep_link_return_url", "https://lms.example/dl"}, {"data", "opaque"}};
  auto c = raygrade::serve::check_launch_claims(p, expectation());
  EXPECT_EQ(c.deep_link_return_url, "https://lms.example/dl");
  EXPECT_EQ(c.deep_link_data, "opaque");
  EXPECT_TRUE(c.instructor());
  // Deep Linking 2.0: the tool may return only the types the platform accepts.
  auto& settings = p["https://purl.imsglobal.org/spec/lti-dl/claim/deep_linking_settings"];
  settings["accept_types"] = {"file", "html"};
  EXPECT_EQ(claims_status(p), 401);
  settings["accept_types"] = {"link", "ltiResourceLink"};
  EXPECT_EQ(claims_status(p), 200);
}

}  // namespace serve_jwt_test
