// A shared library that is not a plugin: it exports a function, but no
// sg_plugin_info.
extern "C" __attribute__((visibility("default"))) int sg_not_a_plugin(void) { return 42; }
