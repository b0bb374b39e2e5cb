// JSON Web Tokens signed RS256 with OpenSSL's EVP interface.
#include "serve/jwt.h"

#include <openssl/bn.h>
#include <openssl/core_names.h>
#include <openssl/param_build.h>
#include <openssl/pem.h>
#include <openssl/rand.h>
#include <openssl/rsa.h>

#include <array>
#include <vector>

#include "core/internal_error.h"

namespace raygrade::serve {

namespace {

constexpr std::string_view kAlphabet =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

struct BnFree {
  void operator()(BIGNUM* b) const { BN_free(b); }
};
using Bn = std::unique_ptr<BIGNUM, BnFree>;

Bn bignum_of(const std::string& bytes) {
  return Bn(BN_bin2bn(reinterpret_cast<const unsigned char*>(bytes.data()),
                      static_cast<int>(bytes.size()), nullptr));
}

std::string bytes_of(const BIGNUM* b) {
  std::string out(static_cast<std::size_t>(BN_num_bytes(b)), '\0');
  BN_bn2bin(b, reinterpret_cast<unsigned char*>(out.data()));
  return out;
}

struct MdCtxFree {
  void operator()(EVP_MD_CTX* c) const { EVP_MD_CTX_free(c); }
};
using MdCtx = std::unique_ptr<EVP_MD_CTX, MdCtxFree>;

}  // namespace

std::string base64url_encode(std::string_view bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::uint32_t buffer = 0;
  int bits = 0;
  for (unsigned char c : bytes) {
    buffer = (buffer << 8) | c;
    bits += 8;
    while (bits >= 6) {
      bits -= 6;
      out += kAlphabet[(buffer >> bits) & 63];
    }
  }
  if (bits > 0) out += kAlphabet[(buffer << (6 - bits)) & 63];
  return out;
}

std::optional<std::string> base64url_decode(std::string_view text) {
  while (!text.empty() && text.back() == '=') text.remove_suffix(1);
  std::string out;
  std::uint32_t buffer = 0;
  int bits = 0;
  for (char c : text) {
    std::size_t v = kAlphabet.find(c);
    if (v == std::string_view::npos) return std::nullopt;
    buffer = (buffer << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 255);
    }
  }
  // Six bits left over cannot end a base64 text (one character alone makes no byte).
  if (bits >= 6) return std::nullopt;
  return out;
}

std::string random_token(std::size_t bytes) {
  std::string raw(bytes, '\0');
  if (RAND_bytes(reinterpret_cast<unsigned char*>(raw.data()), static_cast<int>(bytes)) != 1)
    throw InternalError("random_token: OpenSSL's generator gave no bytes");
  return base64url_encode(raw);
}

PKey rsa_public_key_from_jwk(const nlohmann::json& jwk) {
  if (!jwk.is_object() || jwk.value("kty", "") != "RSA") return nullptr;
  if (!jwk.contains("n") || !jwk["n"].is_string() || !jwk.contains("e") || !jwk["e"].is_string())
    return nullptr;
  auto n = base64url_decode(jwk["n"].get<std::string>());
  auto e = base64url_decode(jwk["e"].get<std::string>());
  if (!n || !e || n->empty() || e->empty()) return nullptr;
  Bn bn_n = bignum_of(*n), bn_e = bignum_of(*e);
  std::unique_ptr<OSSL_PARAM_BLD, decltype(&OSSL_PARAM_BLD_free)> build(OSSL_PARAM_BLD_new(),
                                                                        &OSSL_PARAM_BLD_free);
  if (!bn_n || !bn_e || !build) return nullptr;
  if (!OSSL_PARAM_BLD_push_BN(build.get(), OSSL_PKEY_PARAM_RSA_N, bn_n.get()) ||
      !OSSL_PARAM_BLD_push_BN(build.get(), OSSL_PKEY_PARAM_RSA_E, bn_e.get()))
    return nullptr;
  std::unique_ptr<OSSL_PARAM, decltype(&OSSL_PARAM_free)> params(
      OSSL_PARAM_BLD_to_param(build.get()), &OSSL_PARAM_free);
  std::unique_ptr<EVP_PKEY_CTX, decltype(&EVP_PKEY_CTX_free)> ctx(
      EVP_PKEY_CTX_new_from_name(nullptr, "RSA", nullptr), &EVP_PKEY_CTX_free);
  if (!params || !ctx || EVP_PKEY_fromdata_init(ctx.get()) != 1) return nullptr;
  EVP_PKEY* key = nullptr;
  if (EVP_PKEY_fromdata(ctx.get(), &key, EVP_PKEY_PUBLIC_KEY, params.get()) != 1) return nullptr;
  PKey out(key);
  // A modulus under 2048 bits is below what the Security Framework's RS256 keys are.
  if (EVP_PKEY_get_bits(out.get()) < 2048) return nullptr;
  return out;
}

std::string generate_rsa_pem(int bits) {
  PKey key(EVP_RSA_gen(static_cast<unsigned>(bits)));
  if (!key) throw InternalError("generate_rsa_pem: OpenSSL made no RSA key");
  std::unique_ptr<BIO, decltype(&BIO_free)> bio(BIO_new(BIO_s_mem()), &BIO_free);
  if (!bio ||
      PEM_write_bio_PrivateKey(bio.get(), key.get(), nullptr, nullptr, 0, nullptr, nullptr) != 1)
    throw InternalError("generate_rsa_pem: the key could not be written as PEM");
  char* data = nullptr;
  long size = BIO_get_mem_data(bio.get(), &data);
  return std::string(data, static_cast<std::size_t>(size));
}

PKey private_key_from_pem(const std::string& pem) {
  std::unique_ptr<BIO, decltype(&BIO_free)> bio(
      BIO_new_mem_buf(pem.data(), static_cast<int>(pem.size())), &BIO_free);
  if (!bio) return nullptr;
  return PKey(PEM_read_bio_PrivateKey(bio.get(), nullptr, nullptr, nullptr));
}

nlohmann::json public_jwk(EVP_PKEY* key, const std::string& kid) {
  BIGNUM* n = nullptr;
  BIGNUM* e = nullptr;
  if (EVP_PKEY_get_bn_param(key, OSSL_PKEY_PARAM_RSA_N, &n) != 1 ||
      EVP_PKEY_get_bn_param(key, OSSL_PKEY_PARAM_RSA_E, &e) != 1) {
    BN_free(n);
    throw InternalError("public_jwk: not an RSA key");
  }
  Bn hold_n(n), hold_e(e);
  return {{"kty", "RSA"},
          {"alg", "RS256"},
          {"use", "sig"},
          {"kid", kid},
          {"n", base64url_encode(bytes_of(n))},
          {"e", base64url_encode(bytes_of(e))}};
}

std::string sign_jwt(const nlohmann::json& payload, EVP_PKEY* key, const std::string& kid) {
  nlohmann::json header = {{"alg", "RS256"}, {"typ", "JWT"}, {"kid", kid}};
  std::string input = base64url_encode(header.dump()) + "." + base64url_encode(payload.dump());
  MdCtx ctx(EVP_MD_CTX_new());
  std::size_t size = 0;
  if (!ctx || EVP_DigestSignInit(ctx.get(), nullptr, EVP_sha256(), nullptr, key) != 1 ||
      EVP_DigestSign(ctx.get(), nullptr, &size,
                     reinterpret_cast<const unsigned char*>(input.data()), input.size()) != 1)
    throw InternalError("sign_jwt: OpenSSL could not sign");
  std::string signature(size, '\0');
  if (EVP_DigestSign(ctx.get(), reinterpret_cast<unsigned char*>(signature.data()), &size,
                     reinterpret_cast<const unsigned char*>(input.data()), input.size()) != 1)
    throw InternalError("sign_jwt: OpenSSL could not sign");
  signature.resize(size);
  return input + "." + base64url_encode(signature);
}

DecodedJwt decode_jwt(std::string_view token) {
  std::size_t first = token.find('.');
  std::size_t second = first == std::string_view::npos ? first : token.find('.', first + 1);
  if (second == std::string_view::npos || token.find('.', second + 1) != std::string_view::npos)
    throw Refusal(400, "the id_token is not a signed JWT (three parts separated by dots)");
  auto header = base64url_decode(token.substr(0, first));
  auto payload = base64url_decode(token.substr(first + 1, second - first - 1));
  auto signature = base64url_decode(token.substr(second + 1));
  if (!header || !payload || !signature)
    throw Refusal(400, "the id_token's parts are not base64url");
  DecodedJwt out;
  out.header = nlohmann::json::parse(*header, nullptr, false);
  out.payload = nlohmann::json::parse(*payload, nullptr, false);
  if (!out.header.is_object() || !out.payload.is_object())
    throw Refusal(400, "the id_token's header or payload is not a JSON object");
  out.signing_input = std::string(token.substr(0, second));
  out.signature = std::move(*signature);
  return out;
}

bool verify_rs256(std::string_view input, std::string_view signature, EVP_PKEY* key) {
  if (!key || EVP_PKEY_get_base_id(key) != EVP_PKEY_RSA) return false;
  MdCtx ctx(EVP_MD_CTX_new());
  if (!ctx || EVP_DigestVerifyInit(ctx.get(), nullptr, EVP_sha256(), nullptr, key) != 1)
    return false;
  return EVP_DigestVerify(ctx.get(), reinterpret_cast<const unsigned char*>(signature.data()),
                          signature.size(), reinterpret_cast<const unsigned char*>(input.data()),
                          input.size()) == 1;
}

DecodedJwt verify_platform_jwt(std::string_view token, const KeyLookup& keys) {
  DecodedJwt jwt = decode_jwt(token);
  const nlohmann::json& h = jwt.header;
  if (!h.contains("alg") || !h["alg"].is_string())
    throw Refusal(401, "the id_token's header names no algorithm");
  std::string alg = h["alg"].get<std::string>();
  if (alg != "RS256")
    throw Refusal(401, "the id_token is signed with '" + alg +
                           "': only RS256 with the platform's registered keys is accepted");
  for (const char* named : {"jwk", "jku", "x5u", "x5c"}) {
    if (h.contains(named))
      throw Refusal(401, std::string("the id_token's header names its own key (\"") + named +
                             "\"): only the platform's registered JWKS is trusted");
  }
  if (!h.contains("kid") || !h["kid"].is_string())
    throw Refusal(401, "the id_token's header has no kid");
  PKey key = keys(h["kid"].get<std::string>());
  if (!key) throw Refusal(401, "the id_token's kid is not among the platform's keys (its JWKS)");
  if (!verify_rs256(jwt.signing_input, jwt.signature, key.get()))
    throw Refusal(401, "the id_token's signature is not valid");
  return jwt;
}

}  // namespace raygrade::serve
