#include "core/auth/secret_hash.h"

#include <sodium.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace tt::core::auth {

namespace {

void startSodium() {
    if (sodium_init() < 0) throw std::runtime_error("the password library (libsodium) cannot start");
}

}  // namespace

void checkSecret(const std::string& secret, SecretKind kind) {
    const int length = static_cast<int>(std::min<std::size_t>(secret.size(), kMaxSecretChars + 1));
    if (length > kMaxSecretChars)
        throw std::invalid_argument("the password is too long: at most " + std::to_string(kMaxSecretChars) +
                                    " characters");
    if (kind == SecretKind::Pin) {
        if (!std::all_of(secret.begin(), secret.end(), [](unsigned char c) { return std::isdigit(c) != 0; }))
            throw std::invalid_argument("a PIN has digits only");
        if (length < kMinPinDigits)
            throw std::invalid_argument("the PIN is too short: at least " + std::to_string(kMinPinDigits) + " digits");
        return;
    }
    if (length < kMinPasswordChars)
        throw std::invalid_argument("the password is too short: at least " + std::to_string(kMinPasswordChars) +
                                    " characters");
}

std::string hashSecret(const std::string& secret) {
    startSodium();
    if (secret.size() > static_cast<std::size_t>(kMaxSecretChars))
        throw std::invalid_argument("the password is too long: at most " + std::to_string(kMaxSecretChars) +
                                    " characters");
    char out[crypto_pwhash_STRBYTES];
    if (crypto_pwhash_str_alg(out, secret.data(), secret.size(), crypto_pwhash_OPSLIMIT_INTERACTIVE,
                              crypto_pwhash_MEMLIMIT_INTERACTIVE, crypto_pwhash_ALG_ARGON2ID13) != 0)
        throw std::runtime_error("not enough memory to hash the password (Argon2id needs 64 MiB)");
    return std::string(out);
}

bool verifySecret(const std::string& storedHash, const std::string& secret) {
    startSodium();
    if (secret.size() > static_cast<std::size_t>(kMaxSecretChars) || storedHash.empty() ||
        storedHash.size() >= crypto_pwhash_STRBYTES)
        return false;
    return crypto_pwhash_str_verify(storedHash.c_str(), secret.data(), secret.size()) == 0;
}

}  // namespace tt::core::auth
