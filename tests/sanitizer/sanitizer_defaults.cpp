// Default options of the sanitizers in radview's sanitizer build (RADVIEW_SANITIZE), linked
// into every executable, so that ctest, the shell-driven tests and a developer running
// build-sanitize/radview by hand all get the same checks. The sanitizer runtimes look these
// functions up at start-up; options set in the environment (ASAN_OPTIONS, ...) still win.

extern "C" {

// Any report fails the program: a test that triggers one fails. intercept_tls_get_addr=0:
// LLVM 14's runtime misreads glibc 2.36's dynamic TLS vectors (Mesa's threads have some), and
// its leak checker then crashes scanning a range starting at 0x3dd1; without the interception
// dynamic TLS blocks are scanned as the heap allocations they are.
const char* __asan_default_options() {
  return "check_initialization_order=1:strict_init_order=1:"
         "detect_leaks=1:print_summary=1:intercept_tls_get_addr=0";
}

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

// Leaks that are not radview's: Mesa and LLVM keep allocations for the life of the process
// (driver screens, compiled shader caches) and free them, if ever, after LeakSanitizer runs.
// Assimp 5.2.5 leaks the mesh it was building when its OBJ parser meets some malformed lines
// (tests/fuzz/regressions/import/: a "vx" line among the vertices); radview owns nothing it
// allocated there.
const char* __lsan_default_suppressions() {
  return "leak:libassimp\n"
         "leak:libgallium\n"
         "leak:libLLVM\n"
         "leak:libEGL_mesa\n"
         "leak:libGLX_mesa\n"
         "leak:libglapi\n"
         "leak:libdrm\n"
         "leak:libexpat\n";
}

// Shared libraries stay loaded until the process ends. LeakSanitizer can name a leak's library
// only while it is loaded, and libglvnd unloads Mesa's EGL driver before the leak check runs:
// the driver's process-lifetime allocations would be reported from "<unknown module>", which
// no suppression can match. This definition takes the place of libc's for every library.
int dlclose(void*) { return 0; }

}  // extern "C"
