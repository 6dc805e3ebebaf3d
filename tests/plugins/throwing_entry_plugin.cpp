// A plugin whose entry point throws something that is not a std::exception (an int), as code
// that reports errors by throwing plain values does.
#include "app/plugin.hpp"

NUMERICS_PLUGIN(registry) {
    (void)registry;
    throw 42;
}
