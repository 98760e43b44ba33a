#pragma once

#include <string>

namespace tt::core::auth {

/// What a user logs in with: a password (letters and more) or a PIN (digits only, for gloved hands
/// on the keypad).
enum class SecretKind { Password, Pin };

/// Limits of a secret, characters (bytes of UTF-8).
inline constexpr int kMinPasswordChars = 8;
inline constexpr int kMinPinDigits = 4;
inline constexpr int kMaxSecretChars = 128;

/// Throws std::invalid_argument when `secret` is not a valid secret of `kind` (too short, too long,
/// a PIN with a non-digit), naming the limit.
void checkSecret(const std::string& secret, SecretKind kind);

/// The Argon2id hash of `secret` in the PHC string format ("$argon2id$v=19$m=...") with a random
/// salt and libsodium's interactive limits (crypto_pwhash_str, RFC 9106). Throws std::runtime_error
/// when libsodium cannot start or runs out of memory.
std::string hashSecret(const std::string& secret);

/// Whether `secret` matches `storedHash` (crypto_pwhash_str_verify, constant time); false for a
/// malformed hash or a secret longer than kMaxSecretChars.
bool verifySecret(const std::string& storedHash, const std::string& secret);

}  // namespace tt::core::auth
