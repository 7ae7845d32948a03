// libFuzzer target of the case reader. Built only with clang and
// -DCOLONOSIM_FUZZ=ON (see README, "Patient cases"). Properties checked on
// every input, beyond the sanitizers' own:
// - the reader returns either a case or at least one error, never both;
// - every error has the form file:line: message;
// - a case that reads is written canonically, and the canonical text reads
//   back to the same case and the same text (idempotent round trip);
// - a case that reads translates into a scene without throwing.

#include "case_generator/CaseReader.h"
#include "case_generator/CaseWriter.h"
#include "case_generator/SceneSpec.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace colonosim::cases;
    const ReadResult result =
        readCase(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.xml");
    if (result.ok() == !result.errors.empty()) {
        __builtin_trap();
    }
    for (const std::string& error : result.errors) {
        if (!error.starts_with("fuzz.xml:") || error.find(": ", 9) == std::string::npos) {
            __builtin_trap();
        }
    }
    if (!result.ok()) {
        return 0;
    }
    const std::string canonical = writeCase(*result.value);
    const ReadResult again = readCase(canonical, "canonical.xml");
    if (!again.ok() || writeCase(*again.value) != canonical) {
        __builtin_trap();
    }
    const ReadResult third = readCase(writeCase(*again.value), "third.xml");
    if (!third.ok() || !(*third.value == *again.value)) {
        __builtin_trap();
    }
    try {
        (void)toScene(*again.value);
    } catch (...) {
        __builtin_trap();
    }
    return 0;
}
