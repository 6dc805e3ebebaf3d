// A shared library that is not a plugin: it does not export numerics_plugin_entry.
extern "C" __attribute__((visibility("default"))) int not_a_numerics_plugin() { return 42; }
