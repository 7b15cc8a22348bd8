// A shared library that is not a femto plugin: no femto_plugin_descriptor.
extern "C" __attribute__((visibility("default"))) int test_no_entry_marker() { return 42; }
