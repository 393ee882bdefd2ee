#include "hedge/core/refusal.h"

#include <cstring>

namespace hedge {

const char* refusal_text(Refusal r) noexcept {
  const auto i = static_cast<std::int32_t>(r);
  return i >= 0 && i < kRefusalCount ? kRefusals[i].text : kRefusals[0].text;
}

Refusal refusal_code(const char* text) noexcept {
  if (text == nullptr || *text == '\0') return Refusal::none;
  for (const RefusalEntry& r : kRefusals)
    if (r.text == text) return r.code;
  for (const RefusalEntry& r : kRefusals)
    if (std::strcmp(r.text, text) == 0) return r.code;
  return Refusal::none;
}

}  // namespace hedge
