// The C ABI of the thread policy (hedge/core/threads.h).
#include "hedge/core/threads.h"

#include "capi_internal.h"

using namespace hedge;
using namespace hedge::capi;

extern "C" {

hedge_status hedge_set_max_threads(uint32_t n) {
  return guard([&] { set_max_threads(n); });
}

hedge_status hedge_max_threads(uint32_t* out_n) {
  return guard([&] { need(out_n, "out_n") = max_threads(); });
}

}  // extern "C"
