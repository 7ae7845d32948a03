#include "db/Password.h"

#include "db/Schema.h"

#include <sodium.h>

namespace colonosim::db {

namespace {
void initialiseSodium()
{
    if (sodium_init() < 0) {
        throw DatabaseError("libsodium could not be initialised");
    }
}
}  // namespace

std::string hashPassword(const std::string& password)
{
    initialiseSodium();
    if (password.size() < kMinPasswordLength || password.size() > kMaxPasswordLength) {
        throw DatabaseError("password length " + std::to_string(password.size()) + " is out of range " +
                            std::to_string(kMinPasswordLength) + "-" + std::to_string(kMaxPasswordLength) +
                            " characters");
    }
    char out[crypto_pwhash_STRBYTES];
    if (crypto_pwhash_str(out, password.data(), password.size(), crypto_pwhash_OPSLIMIT_INTERACTIVE,
                          crypto_pwhash_MEMLIMIT_INTERACTIVE) != 0) {
        throw DatabaseError("out of memory while hashing a password");
    }
    return out;
}

bool verifyPassword(const std::string& hash, const std::string& password)
{
    initialiseSodium();
    return crypto_pwhash_str_verify(hash.c_str(), password.data(), password.size()) == 0;
}

std::string randomPassword()
{
    initialiseSodium();
    static constexpr char alphabet[] = "abcdefghjkmnpqrstuvwxyzABCDEFGHJKLMNPQRSTUVWXYZ23456789";
    std::string out;
    for (int i = 0; i < 20; ++i) {
        out += alphabet[randombytes_uniform(sizeof(alphabet) - 1)];
    }
    return out;
}

}  // namespace colonosim::db
