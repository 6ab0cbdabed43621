// libFuzzer target: read_vtu_text (see fuzz_checks.hpp). A dgwarp::Error is the
// expected answer to a malformed input; anything else escapes and is reported.
#include <cstddef>
#include <cstdint>

#include "dgwarp/core/error.hpp"
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        dgwarp::fuzz::check_vtu({data, size});
    } catch (const dgwarp::Error&) {
    }
    return 0;
}
