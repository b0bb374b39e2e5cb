// JSON Web Tokens signed RS256, with OpenSSL's EVP interface alone: keys from a JWKS's RSA
// modulus and exponent, the tool's own key (PEM), signing and verifying. Nothing here reads a
// key named by the token itself.
#pragma once

#include <openssl/evp.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raygrade::serve {

// Why a request is refused: the HTTP status (400 bad request, 401 bad token, 403 wrong
// browser or user) and a sentence for the page that says so.
class Refusal : public std::runtime_error {
 public:
  Refusal(int status, const std::string& reason) : std::runtime_error(reason), status_(status) {}
  int status() const { return status_; }

 private:
  int status_;
};

struct PKeyFree {
  void operator()(EVP_PKEY* k) const { EVP_PKEY_free(k); }
};
using PKey = std::unique_ptr<EVP_PKEY, PKeyFree>;

std::string base64url_encode(std::string_view bytes);
// Nothing when `text` holds a character outside the base64url alphabet or padding.
std::optional<std::string> base64url_decode(std::string_view text);

// Random bytes from OpenSSL's generator, as base64url text (`bytes` of entropy).
std::string random_token(std::size_t bytes = 32);

// An RSA public key from a JWK ({"kty": "RSA", "n", "e"}); null when it is not one.
PKey rsa_public_key_from_jwk(const nlohmann::json& jwk);
// A new RSA key of `bits`, as PKCS#8 PEM.
std::string generate_rsa_pem(int bits = 2048);
// The private key of a PEM text; null when it is not one.
PKey private_key_from_pem(const std::string& pem);
// The public half of `key` as a JWK: kty, n, e, kid, alg RS256, use sig.
nlohmann::json public_jwk(EVP_PKEY* key, const std::string& kid);

// header.payload.signature, signed RS256 with `key`; the header is {"alg": "RS256", "typ":
// "JWT", "kid": kid}.
std::string sign_jwt(const nlohmann::json& payload, EVP_PKEY* key, const std::string& kid);

// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct DecodedJwt {
  nlohmann::json header;
  nlohmann::json payload;
  std::string signing_input;  // header.payload as sent
  std::string signature;      // bytes
};

// The three parts of a compact JWS, decoded; throws Refusal (400) when it is not one.
DecodedJwt decode_jwt(std::string_view token);

// Whether `signature` is RS256 (RSASSA-PKCS1-v1_5 with SHA-256) of `input` by `key`.
bool verify_rs256(std::string_view input, std::string_view signature, EVP_PKEY* key);

// The platform's key for a kid (fetching its JWKS again when the kid is unknown), or null.
using KeyLookup = std::function<PKey(const std::string& kid)>;

// A token checked as the Security Framework asks of its header and signature: alg RS256 and
// nothing else (no "none", no HMAC), no key named in the header (jwk, jku, x5u, x5c), a kid the
// platform's JWKS holds, and a valid signature. Throws Refusal (401) with the reason.
DecodedJwt verify_platform_jwt(std::string_view token, const KeyLookup& keys);

}  // namespace raygrade::serve
