// Test fixture: a shared library without the SubdivKit entry point. Loading it must be
// refused ("no entry point"), and the other plugins must still work.
extern "C" __attribute__((visibility("default"))) int not_a_subdivkit_plugin() { return 42; }
