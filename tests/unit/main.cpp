// The unit tests' main: the build tree's plugins and a probe cache of their own, also when
// the binary runs outside ctest (a variable already set wins).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdlib>

// Read by the sanitizer runtimes at start-up (a build with -DSPHKERN_SANITIZE=ON); unused otherwise.
extern "C" const char* __asan_default_options() { return "handle_segv=0:detect_leaks=1"; }
extern "C" const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

int main(int argc, char** argv)
{
    ::setenv("SPHKERN_PLUGIN_PATH", SPHKERN_BUILD_DIR "/plugins", 0);
    ::setenv("XDG_CACHE_HOME", SPHKERN_BUILD_DIR "/test-cache", 0);
    return doctest::Context(argc, argv).run();
}
