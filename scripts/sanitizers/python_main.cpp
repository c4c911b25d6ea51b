// The Python interpreter for the ThreadSanitizer stage (scripts/check-sanitizers.sh): CPython's own
// main(), linked into an executable built with -fsanitize=thread so that the sanitizer's runtime is
// part of the program from its start and the thread-sanitized extension finds it when imported.
#include <Python.h>

int main(int argc, char** argv) { return Py_BytesMain(argc, argv); }
