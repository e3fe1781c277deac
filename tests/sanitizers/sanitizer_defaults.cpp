// Run-time defaults of the sanitized build (CENTREC_SANITIZE), compiled into centrec and every
// test executable so that they hold however the binary is started (ctest, a test that runs
// centrec as a child, a developer's shell): no environment variable has to reach the process.
//
// allocator_may_return_null: a corrupted HDF5 size field makes libhdf5 ask for ~1 TB (a
// flipped byte in the fuzz test's film file asked for 0xd900000068 bytes); without the
// sanitizers malloc returns null and libhdf5 refuses the file cleanly, and so it must here.
//
// leak:libhdf5_serial: libhdf5 leaks a small block (56-104 bytes, allocated inside the
// library) when it gives up opening a corrupted file; the leak is the library's, at a
// refusal that ends the process (docs/reliability.md, the sanitizer build).

extern "C" const char* __asan_default_options() { return "allocator_may_return_null=1"; }

extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }

extern "C" const char* __lsan_default_suppressions() { return "leak:libhdf5_serial.so\n"; }
