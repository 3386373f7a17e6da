/* Linked into every executable of the sanitizer build (scripts/sanitize.sh).
 *
 * Shared libraries are never unloaded. Mesa's EGL unloads its driver at exit; memory
 * that the driver's globals still pointed to then looks leaked, allocated from an
 * "unknown module". With the libraries kept, LeakSanitizer sees those pointers and
 * reports only real leaks, so the GL, golden, command-line and GUI tests run with leak
 * checking on.
 *
 * The leak check runs before the static destructors of any library loaded at run time,
 * not after them. LeakSanitizer checks at exit, last; by then the destructors of
 * OpenImageIO's dependencies (log4cplus, through OpenVDB: the image codec's module) are
 * ending the threads they started, and a thread that ends while LeakSanitizer stops the
 * world crashes its tracer ("Tracer caught signal 11 ... LeakSanitizer has encountered
 * a fatal error", google/sanitizers#1353), failing a test that passed: CI stops 47 and
 * 48. An exit handler registered after each dlopen runs before the destructors that the
 * library's loading registered, while its threads still wait for work; the check it
 * makes is the process's only one (LeakSanitizer's own at exit then does nothing).
 * Memory that globals hold is reachable either way, so the answer is the same. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <sanitizer/lsan_interface.h>
#include <stdlib.h>

int dlclose(void* handle) {
    (void)handle;
    return 0;
}

static void check_leaks_now(void) { __lsan_do_leak_check(); }

void* dlopen(const char* file, int mode) {
    static void* (*next)(const char*, int);
    if (!next)
        next = (void* (*)(const char*, int))dlsym(RTLD_NEXT, "dlopen");
    void* handle = next(file, mode);
    if (handle)
        atexit(check_leaks_now);
    return handle;
}
