// LeakSanitizer's built-in suppressions for every sanitized fractalis executable (the CLI, the
// scene host, the tests): leaks that belong to the OpenCL implementation, not to fractalis.
//
// PoCL keeps the LLVM context it compiles kernels in, and everything LLVM built in it, for the
// life of the process and never frees it. LeakSanitizer reports that at exit only when a kernel
// was compiled rather than taken from PoCL's cache, so without this a sanitized run passes or
// fails by the state of the cache (a cold cache made `vet-scene` exit 1 and hot reload refuse
// a good plugin). Our own allocations stay checked: a leak whose stack has no PoCL or LLVM frame
// is still reported. OpenCL objects we fail to release are allocated inside PoCL and so are not;
// the hot-reload test counts those (threads, open files, mappings) instead.
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libpocl.so\n"
         "leak:libLLVM\n";
}
// Without the table of what was suppressed at every exit: it is the same table each time.
extern "C" const char* __lsan_default_options() {
  return "print_suppressions=0";
}
#endif
