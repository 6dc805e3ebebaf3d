// The error of a setting or choice a user made: its message names the key, what was expected
// and what was found.
#pragma once

#include <stdexcept>

namespace num::sph {

struct SettingsError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace num::sph
