// Numbers on the command line (tools/hedge/numbers.cpp): overflow, non-finite values and bounds
// said in words, for every numeric option of every command.
#include <string>
#include <vector>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

//! A usage error whose one line holds every one of `parts` and none of the old range text.
void expect_refusal(const HedgeCli& t, const Result& r, const std::vector<std::string>& parts) {
  EXPECT_EQ(r.code, 2) << r.err;
  const auto err = lines(r.err);
  ASSERT_EQ(err.size(), 1u) << r.err;
  for (const std::string& p : parts)
    EXPECT_NE(err[0].find(p), std::string::npos) << "no '" << p << "' in " << err[0];
  EXPECT_EQ(err[0].find("1797"), std::string::npos) << err[0];
  EXPECT_EQ(err[0].find("not in range"), std::string::npos) << err[0];
  (void)t;
}

TEST_F(HedgeCli, NumbersOutOfRangeSayTheBoundInWords) {
  const std::string in = data("tet.obj"), out = tmp("o.obj").string();
  expect_refusal(*this, run({"decimate", in, out, "--faces", "0"}), {"--faces", "must be at least 1, got 0"});
  expect_refusal(*this, run({"decimate", in, out, "--max-error", "-1"}),
                 {"--max-error", "must be 0 or more, got -1"});
  expect_refusal(*this, run({"decimate", in, out, "--ratio", "0"}),
                 {"--ratio", "must be more than 0 and at most 1"});
  expect_refusal(*this,
                 run({"fracture", in, "--impact", "0,0,0", "-o", tmp("f").string(), "--thickness", "-1"}),
                 {"--thickness", "must be 0 or more, got -1"});
  expect_refusal(*this, run({"fracture", in, "--impact", "0,0,0", "-o", tmp("f").string(), "--density", "0"}),
                 {"--density", "must be positive, got 0"});
  expect_refusal(*this, run({"subdivide", in, out, "--steps", "13"}),
                 {"--steps", "must be from 0 to 12, got 13"});
  expect_refusal(*this, run({"render", in, "-o", tmp("p.png").string(), "--fov", "200"}),
                 {"--fov", "must be from 0 to 179, got 200"});
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(HedgeCli, NumbersThatOverflowAreRefusedNotWrapped) {
  const std::string in = data("tet.obj");
  // The largest 64-bit number: once taken as that many samples, of which 8355 were measured.
  expect_refusal(*this, run({"distance", in, in, "--samples", "18446744073709551615"}),
                 {"--samples", "must be from 0 to 100000000"});
  expect_refusal(*this, run({"distance", in, in, "--samples", "99999999999999999999999"}),
                 {"--samples", "too large"});
  // sscanf made 1215752191 of it.
  const Result size = run({"render", in, "-o", tmp("p.png").string(), "--size", "99999999999x2"});
  expect_refusal(*this, size, {"--size", "99999999999", "from 1 to 16384"});
  EXPECT_EQ(size.err.find("1215752191"), std::string::npos) << size.err;
  expect_refusal(*this, run({"render", in, "-o", tmp("p.png").string(), "--size", "800x600x2"}),
                 {"WIDTHxHEIGHT"});
  expect_refusal(*this, run({"decimate", in, tmp("o.obj").string(), "--faces", "-1"}),
                 {"--faces", "at least 1"});
  expect_refusal(*this, run({"stress", in, "--ops", "1e3"}), {"--ops", "not a whole number"});
  expect_refusal(*this, run({"decimate", in, tmp("o.obj").string(), "--max-error", "1e999"}),
                 {"--max-error", "beyond the range of a number"});
}

TEST_F(HedgeCli, NonFiniteNumbersAreRefusedNamingTheOption) {
  const std::string in = data("tet.obj");
  // Once "the eye and the target must differ".
  const Result eye =
      run({"render", in, "-o", tmp("p.png").string(), "--eye", "nan,0,0", "--target", "0,0,0"});
  expect_refusal(*this, eye, {"--eye", "'nan' is not a finite number"});
  EXPECT_EQ(eye.err.find("must differ"), std::string::npos) << eye.err;
  expect_refusal(*this,
                 run({"render", in, "-o", tmp("p.png").string(), "--eye", "1,1,1", "--target", "0,inf,0"}),
                 {"--target", "'inf' is not a finite number"});
  expect_refusal(*this, run({"fracture", in, "--impact", "0,nan,0", "-o", tmp("f").string()}),
                 {"--impact", "'nan' is not a finite number"});
  expect_refusal(*this, run({"smooth", in, tmp("o.obj").string(), "--lambda", "nan"}),
                 {"--lambda", "not a finite"});
  expect_refusal(*this, run({"decimate", in, tmp("o.obj").string(), "--max-error", "inf"}),
                 {"--max-error", "not a finite"});
}

TEST_F(HedgeCli, EveryNumericOptionRefusesNaNAndNegativesInWords) {
  const std::string in = data("tet.obj"), out = tmp("o.obj").string(), png = tmp("p.png").string();
  struct Case {
    std::vector<std::string> command;
    std::string option;
  };
  const std::vector<Case> cases = {
      {{"decimate", in, out}, "--ratio"},
      {{"decimate", in, out}, "--faces"},
      {{"decimate", in, out}, "--vertices"},
      {{"decimate", in, out}, "--max-error"},
      {{"decimate", in, out}, "--boundary-weight"},
      {{"decimate", in, out}, "--feature-angle"},
      {{"decimate", in, out}, "--feature-weight"},
      {{"decimate", in, out}, "--attribute-weight"},
      {{"decimate", in, out}, "--max-normal-change"},
      {{"decimate", in, out, "--faces", "2"}, "--weld-eps"},
      {{"distance", in, in}, "--samples"},
      {{"distance", in, in}, "--seed"},
      {{"fracture", in, "--impact", "0,0,0", "-o", tmp("f").string()}, "--seed"},
      {{"fracture", in, "--impact", "0,0,0", "-o", tmp("f").string()}, "--thickness"},
      {{"fracture", in, "--impact", "0,0,0", "-o", tmp("f").string()}, "--density"},
      {{"fracture", in, "--impact", "0,0,0", "-o", tmp("f").string()}, "--tolerance"},
      {{"render", in, "-o", png}, "--columns"},
      {{"render", in, "-o", png}, "--fov"},
      {{"render", in, "-o", png}, "--feature-angle"},
      {{"render", in, "-o", png}, "--supersample"},
      {{"render", in, "-o", png}, "--threads"},
      {{"render", in, "-o", png}, "--max-faces"},
      {{"render-buffers", in}, "--edits"},
      {{"render-buffers", in}, "--seed"},
      {{"stress", in}, "--ops"},
      {{"stress", in}, "--seed"},
      {{"stress", in}, "--validate-every"},
      {{"smooth", in, out}, "--iterations"},
      {{"smooth", in, out}, "--lambda"},
      {{"smooth", in, out}, "--mu"},
      {{"subdivide", in, out}, "--steps"},
      {{"tour", in, "--out", tmp("t").string()}, "--panel"},
      {{"tour", in, "--out", tmp("t").string()}, "--max-faces"},
  };
  for (const Case& c : cases) {
    for (const std::string value : {"nan", "-1"}) {
      if (value == "-1" && (c.option == "--lambda" || c.option == "--mu")) continue;  // any finite number
      std::vector<std::string> args = c.command;
      args.push_back(c.option);
      args.push_back(value);
      SCOPED_TRACE(c.option + " " + value);
      expect_refusal(*this, run(args), {c.option});
    }
  }
}

}  // namespace
