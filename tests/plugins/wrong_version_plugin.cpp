// A library with the entry point of a plugin built against another plugin API version.
#include "app/plugin.hpp"

extern "C" __attribute__((visibility("default"))) int numerics_plugin_entry(
    int, num::app::plugin::Registry*) {
    return NUMERICS_PLUGIN_API_VERSION + 998;
}
