// The layering tests compile this file with one layer's include root (see tests/CMakeLists.txt):
// a header of a layer it uses must be found, a header of any other layer must not.
#include HEDGE_PROBE_HEADER

int main() { return 0; }
