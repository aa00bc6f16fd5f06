#pragma once
// The libFuzzer targets' bodies (tests/fuzz/fuzz_<name>.cpp) and what each checks: bad
// input is InputError with valid UTF-8 messages that name a field; anything else (a
// broken contract is std::logic_error) escapes, and libFuzzer reports it as a crash with
// its reproducer. Copy that file to tests/fuzz/regressions/<name>/: test_fuzz_regressions
// runs every file there through the same body under ctest.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/model/diagnostics.hpp"
#include "core/model/utf8_text.hpp"

namespace ll::fuzz {

int sceneLoader(const std::uint8_t* data, std::size_t size);  // scene file → reader and checks
int expression(const std::uint8_t* data, std::size_t size);   // a numeric field's expression
int lagrangian(const std::uint8_t* data, std::size_t size);   // E_kin, E_pot, Q typed by hand
int evalState(const std::uint8_t* data, std::size_t size);    // eval of an example at a fuzzed state
int answer(const std::uint8_t* data, std::size_t size);       // a student's answer and an entry's name (check-answer)
int urdf(const std::uint8_t* data, std::size_t size);         // a URDF file through lagrangelab import

inline void require(bool ok, const char* what) {
    if (!ok) throw std::logic_error(std::string("contract broken: ") + what);
}

inline void checkRefusal(const InputError& e) {
    require(hasErrors(e.diagnostics()), "an InputError without an error");
    for (const Diagnostic& d : e.diagnostics()) {
        require(!d.field.empty(), "a diagnostic names no field");
        require(isValidUtf8(d.field) && isValidUtf8(d.message.english()), "a diagnostic is not UTF-8");
    }
}

}  // namespace ll::fuzz
