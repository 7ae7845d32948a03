#pragma once
/// \file
/// Ed25519 signatures (libsodium) of certification reports. The signed
/// message binds the report's bytes to the database's record of it:
///   "colonosim-certificate-v1\nuser=NAME\nsha256=HEX(SHA-256 of the PDF bytes)\n"
/// The PDF carries the signature in a comment line appended after its %%EOF
/// (PDF readers ignore it):
///   %COLONOSIM-SIGNATURE v1 user=NAME public_key=HEX signature=HEX
/// and the certificates table keeps the same hash, signature and public key.
/// The signing key lives next to the database (FILE.signing-key, mode 0600),
/// created on first use.

#include <filesystem>
#include <optional>
#include <string>

namespace colonosim::reports {

struct SignedTrailer {
    std::string user, publicKey, signature;  ///< hex
    std::string content;                     ///< the PDF bytes before the trailer
};

[[nodiscard]] std::string sha256Hex(const std::string& bytes);
[[nodiscard]] std::string signedMessage(const std::string& user, const std::string& contentSha256);

struct SigningKey {
    std::string publicKeyHex;
    std::string secretKey;  ///< raw bytes
};
/// Loads or creates the key file. Throws std::runtime_error naming the file.
[[nodiscard]] SigningKey signingKey(const std::filesystem::path& keyFile);
[[nodiscard]] std::string sign(const SigningKey& key, const std::string& message);  ///< hex

[[nodiscard]] std::string trailerLine(const std::string& user, const std::string& publicKey,
                                      const std::string& signature);
/// nullopt when the file has no (well-formed) trailer.
[[nodiscard]] std::optional<SignedTrailer> splitTrailer(const std::string& file);
[[nodiscard]] bool verifySignature(const std::string& publicKeyHex, const std::string& signatureHex,
                                   const std::string& message);

}  // namespace colonosim::reports
