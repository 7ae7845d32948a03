#pragma once
/// \file
/// Password hashes: Argon2id through libsodium's crypto_pwhash_str, at its
/// "interactive" limits (2 passes, 64 MiB; libsodium's recommendation for
/// online logins). The string keeps algorithm, limits and salt, so a hash
/// verifies even after the limits change.

#include <string>

namespace colonosim::db {

/// Refuses passwords shorter than kMinPasswordLength (the message says so).
[[nodiscard]] std::string hashPassword(const std::string& password);
[[nodiscard]] bool verifyPassword(const std::string& hash, const std::string& password);
/// A random password of 20 characters from an unambiguous alphabet.
[[nodiscard]] std::string randomPassword();

inline constexpr size_t kMinPasswordLength = 8;  ///< characters; NIST SP 800-63B minimum
inline constexpr size_t kMaxPasswordLength = 256;

}  // namespace colonosim::db
