#include "trainer_ui/reports/CertificateSignature.h"

#include <sodium.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <vector>

namespace colonosim::reports {

namespace {
void initialise()
{
    if (sodium_init() < 0) {
        throw std::runtime_error("libsodium could not be initialised");
    }
}

std::string hex(const unsigned char* data, size_t size)
{
    std::string out(size * 2 + 1, '\0');
    sodium_bin2hex(out.data(), out.size(), data, size);
    out.pop_back();
    return out;
}

std::optional<std::vector<unsigned char>> unhex(const std::string& text, size_t size)
{
    std::vector<unsigned char> out(size);
    size_t length = 0;
    if (sodium_hex2bin(out.data(), out.size(), text.data(), text.size(), nullptr, &length, nullptr) != 0 ||
        length != size || text.size() != size * 2) {
        return std::nullopt;
    }
    return out;
}

constexpr const char* kTrailer = "%COLONOSIM-SIGNATURE v1 ";
}  // namespace

std::string sha256Hex(const std::string& bytes)
{
    initialise();
    unsigned char digest[crypto_hash_sha256_BYTES];
    crypto_hash_sha256(digest, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
    return hex(digest, sizeof(digest));
}

std::string signedMessage(const std::string& user, const std::string& contentSha256)
{
    return "colonosim-certificate-v1\nuser=" + user + "\nsha256=" + contentSha256 + "\n";
}

SigningKey signingKey(const std::filesystem::path& keyFile)
{
    initialise();
    SigningKey key;
    std::ifstream in(keyFile);
    std::string text;
    if (in && std::getline(in, text)) {
        const auto secret = unhex(text, crypto_sign_SECRETKEYBYTES);
        if (!secret) {
            throw std::runtime_error(keyFile.string() + ": not a signing key (" +
                                     std::to_string(crypto_sign_SECRETKEYBYTES * 2) +
                                     " hex digits expected)");
        }
        key.secretKey.assign(secret->begin(), secret->end());
        unsigned char pk[crypto_sign_PUBLICKEYBYTES];
        crypto_sign_ed25519_sk_to_pk(pk, secret->data());
        key.publicKeyHex = hex(pk, sizeof(pk));
        return key;
    }
    unsigned char pk[crypto_sign_PUBLICKEYBYTES];
    unsigned char sk[crypto_sign_SECRETKEYBYTES];
    crypto_sign_keypair(pk, sk);
    {
        std::ofstream out(keyFile);
        out << hex(sk, sizeof(sk)) << '\n';
        if (!out) {
            throw std::runtime_error(keyFile.string() + ": cannot write the signing key");
        }
    }
    ::chmod(keyFile.c_str(), S_IRUSR | S_IWUSR);
    key.secretKey.assign(reinterpret_cast<const char*>(sk), sizeof(sk));
    key.publicKeyHex = hex(pk, sizeof(pk));
    sodium_memzero(sk, sizeof(sk));
    return key;
}

std::string sign(const SigningKey& key, const std::string& message)
{
    initialise();
    unsigned char signature[crypto_sign_BYTES];
    crypto_sign_detached(signature, nullptr, reinterpret_cast<const unsigned char*>(message.data()),
                         message.size(), reinterpret_cast<const unsigned char*>(key.secretKey.data()));
    return hex(signature, sizeof(signature));
}

std::string trailerLine(const std::string& user, const std::string& publicKey, const std::string& signature)
{
    return std::string(kTrailer) + "user=" + user + " public_key=" + publicKey + " signature=" + signature +
           "\n";
}

std::optional<SignedTrailer> splitTrailer(const std::string& file)
{
    const size_t at = file.rfind(kTrailer);
    if (at == std::string::npos) {
        return std::nullopt;
    }
    static const std::regex line(
        R"(%COLONOSIM-SIGNATURE v1 user=(\S+) public_key=([0-9a-f]+) signature=([0-9a-f]+)\n)");
    std::smatch match;
    const std::string tail = file.substr(at);
    if (!std::regex_match(tail, match, line)) {
        return std::nullopt;
    }
    return SignedTrailer{match[1], match[2], match[3], file.substr(0, at)};
}

bool verifySignature(const std::string& publicKeyHex, const std::string& signatureHex,
                     const std::string& message)
{
    initialise();
    const auto pk = unhex(publicKeyHex, crypto_sign_PUBLICKEYBYTES);
    const auto signature = unhex(signatureHex, crypto_sign_BYTES);
    return pk && signature &&
           crypto_sign_verify_detached(signature->data(),
                                       reinterpret_cast<const unsigned char*>(message.data()), message.size(),
                                       pk->data()) == 0;
}

}  // namespace colonosim::reports
