#include "hedge/error.h"

#include <gtest/gtest.h>

namespace hedge {
namespace {

TEST(Error, IoErrorNamesPathLineAndOffset) {
  IoError a("mesh.obj", 12, -1, "expected a vertex index");
  EXPECT_STREQ(a.what(), "mesh.obj:12: expected a vertex index");
  EXPECT_EQ(a.line(), 12u);
  IoError b("mesh.stl", 0, 84, "truncated triangle");
  EXPECT_STREQ(b.what(), "mesh.stl (byte 84): truncated triangle");
  IoError c("", 0, -1, "empty");
  EXPECT_STREQ(c.what(), "<memory>: empty");
  const Error& base = b;
  EXPECT_EQ(std::string(base.what()).rfind("mesh.stl", 0), 0u);
}

TEST(Error, TopologyErrorCarriesElements) {
  TopologyError e("bad", {3, 4}, {7});
  EXPECT_EQ(e.vertices(), (std::vector<std::uint32_t>{3, 4}));
  EXPECT_EQ(e.faces(), (std::vector<std::uint32_t>{7}));
}

TEST(Error, BytesTextPicksTheUnit) {
  EXPECT_EQ(bytes_text(0), "0 bytes");
  EXPECT_EQ(bytes_text(1000), "1000 bytes");
  EXPECT_EQ(bytes_text(1024), "1.0 KiB");
  EXPECT_EQ(bytes_text(1.5 * 1024 * 1024 * 1024), "1.5 GiB");
}

}  // namespace
}  // namespace hedge
