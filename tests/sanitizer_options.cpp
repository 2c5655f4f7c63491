// sanitizer_options.cpp — AddressSanitizer's options for the test programs, as host/main.cpp sets
// them for fractalis: a process that loads PoCL beside OpenEXR's, FFmpeg's and stb_image's
// libraries has more dynamic-TLS modules than GCC 12's LeakSanitizer tracks correctly, and at
// exit its tracer can crash on a stale range ("Tracer caught signal 11"), failing a program whose
// every test passed (cli_test did, once stb_image joined the host library). Leaks are still
// detected without intercepting __tls_get_addr.
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __asan_default_options() {
  return "intercept_tls_get_addr=0";
}
#endif
