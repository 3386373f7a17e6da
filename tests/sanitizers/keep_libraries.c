/* Linked into every executable of the sanitizer build (scripts/sanitize.sh): shared
 * libraries are never unloaded. Mesa's EGL unloads its driver at exit; memory that the
 * driver's globals still pointed to then looks leaked, allocated from an "unknown
 * module". With the libraries kept, LeakSanitizer sees those pointers and reports only
 * real leaks, so the GL, golden, command-line and GUI tests run with leak checking on. */
int dlclose(void* handle) {
    (void)handle;
    return 0;
}
