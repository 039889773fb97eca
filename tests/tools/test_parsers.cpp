// The parsers of files a user or a list author gives the tools, without the
// benches: each refusal is one line naming the place, and the inputs the
// fuzzers found once are regression tests here. Runs in the default build
// and under ASan+UBSan (build-san).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "fst_check.h"
#include "regress.h"
#include "scenario_json.h"
#include "scurve/cli/user_input.h"
#include "scurve/reg_encode.h"
#include "trace_diff.h"

namespace sc {
namespace {

std::string fst_header() {
  std::string h(330, '\0');
  h[7] = char(329 >> 8);  // section length 329, big-endian
  h[8] = char(329 & 0xff);
  const double e = 2.7182818284590452354;
  std::memcpy(h.data() + 25, &e, 8);
  return h;
}

std::string block(uint8_t type, const std::string& payload) {
  std::string b(1, char(type));
  const uint64_t len = payload.size() + 8;
  for (int i = 7; i >= 0; --i) b.push_back(char(uint8_t(len >> (8 * i))));
  return b + payload;
}

TEST(FstCheck, AcceptsAWellFormedBlockChainAndRefusesDamagedOnes) {
  const std::string ok = fst_header() + block(1, "data") + block(3, "g") + block(4, "h");
  auto check = [](const std::string& s) { return fst_check(reinterpret_cast<const uint8_t*>(s.data()), s.size()); };
  EXPECT_EQ(check(ok), "");
  EXPECT_NE(check(ok.substr(0, ok.size() - 1)), "");                      // truncated last block
  EXPECT_NE(check(ok + "x"), "");                                         // trailing byte
  EXPECT_NE(check(fst_header() + block(1, "data") + block(4, "h")), "");  // no geometry
  EXPECT_NE(check(fst_header() + block(255, "x") + block(3, "g") + block(4, "h")), "");  // unfinished
  EXPECT_NE(check(ok.substr(0, 100)), "");
  std::string bad_len = ok;
  bad_len[331] = char(0x80);  // the first block's length: 2^63 and more
  EXPECT_NE(check(bad_len), "");
}

TEST(FstRecords, RoundTripAndRefuseInconsistentStreams) {
  std::string s = encode_fst_header(100, {"top.a", "top.b"});
  append_fst_change(s, 0, 0, "0");
  append_fst_change(s, 1, 0, "1");
  append_fst_change(s, 0, 50, "1");
  append_fst_change(s, 0, 50, "0");  // last write of a time step wins
  const FstSignals f = decode_fst_signals(s);
  ASSERT_EQ(f.names.size(), 2u);
  EXPECT_EQ(f.end_time, 100u);
  ASSERT_EQ(f.changes[0].size(), 2u);
  EXPECT_EQ(f.changes[0][1].second, "0");
  std::string bad = s;
  append_fst_change(bad, 2, 60, "1");  // no signal 2
  EXPECT_THROW(decode_fst_signals(bad), std::runtime_error);
  bad = s;
  append_fst_change(bad, 0, 10, "1");  // back in time
  EXPECT_THROW(decode_fst_signals(bad), std::runtime_error);
  EXPECT_THROW(decode_fst_signals(s.substr(0, s.size() - 3)), std::runtime_error);
}

TEST(ScenarioJson, RefusalsNameTheKey) {
  ControllerInput c;
  PlantConfig p;
  EXPECT_EQ(apply_scenario_json(R"({"controller": {"k_p": 0.004}})", c, p), "");
  EXPECT_NE(apply_scenario_json(R"({"controller": {"k_p": -1}})", c, p).find("scenario.controller.k_p"),
            std::string::npos);
  EXPECT_NE(apply_scenario_json(R"({"plant": {"f_n": "x"}})", c, p).find("scenario.plant.f_n"), std::string::npos);
  EXPECT_NE(apply_scenario_json("{", c, p).find("not JSON"), std::string::npos);
}

TEST(UartResponse, OnlyWellFormedFramesAreAccepted) {
  std::vector<uint8_t> w = {0x5A, 0x00, 0};
  w[2] = scurve::crc8(w.data() + 1, 1);
  // The response sync is whatever the library defines; build one from a frame it accepts.
  for (uint8_t sync = 0; sync < 255; ++sync) {
    w[0] = sync;
    if (scurve::parse_uart_response(w, false).ok) break;
  }
  EXPECT_TRUE(scurve::parse_uart_response(w, false).ok);
  std::vector<uint8_t> bad = w;
  bad[2] ^= 1;
  EXPECT_FALSE(scurve::parse_uart_response(bad, false).ok);
  EXPECT_FALSE(scurve::parse_uart_response({}, true).ok);
  EXPECT_FALSE(scurve::parse_uart_response({w[0]}, true).ok);
}

TEST(KinTraceStreams, ATraceIsIdenticalToItself) {
  const std::string t =
      "# scurve-kin-trace v1 source=rtl decimate=10 held=step\nclock,step,ref_vel\n0,0,5\n10,1,6\n# end_clock=20\n";
  std::istringstream a(t), b(t);
  EXPECT_TRUE(diff_kin_streams(a, "a", b, "b").identical());
}

// Inputs the fuzzers failed on (tests/fuzz), one test each.

// A message must stay one printable line: text from the file is escaped.
void expect_printable_line(const std::string& msg) {
  EXPECT_FALSE(msg.empty());
  for (char c : msg) EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) << msg;
}

TEST(ParserFindings, FstRecordErrorShowsASignalNameWithANewlineEscaped) {
  std::string s = encode_fst_header(0, {"a\nb\x1b[2J"});
  append_fst_change(s, 0, 5, "1");
  append_fst_change(s, 0, 4, "0");
  try {
    decode_fst_signals(s);
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    expect_printable_line(e.what());
    EXPECT_NE(std::string(e.what()).find("a\\x0ab"), std::string::npos) << e.what();
  }
}

TEST(ParserFindings, ScenarioNotJsonShowsTheQuotedInputEscaped) {
  // The JSON parser quotes the text it last read: a DEL byte in a string.
  ControllerInput c;
  PlantConfig p;
  const std::string e = apply_scenario_json("{\n\"_comment\": \"N\x7f\n", c, p);
  EXPECT_NE(e.find("not JSON"), std::string::npos) << e;
  expect_printable_line(e);
}

TEST(ParserFindings, KinTraceErrorShowsControlCharactersEscaped) {
  const std::string t = "# scurve-kin-trace v1\nclock,step\r\n0,1\x1b\n";
  std::istringstream a(t), b(t);
  try {
    diff_kin_streams(a, "a", b, "b");
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    expect_printable_line(e.what());
  }
}

// A random entry whose moves never fit its max_clocks made every seed draw
// the planner 1,000 times (a libFuzzer timeout); a list could make any
// number of seeds do so. Now each seed draws at most kDrawsPerSeed times
// and a list at most its budget, and either is a refusal naming the field.
TEST(ParserFindings, RandomEntriesDrawThePlannerABoundedNumberOfTimes) {
  using regress::expand_list;
  const nlohmann::json never_fits = nlohmann::json::parse(R"({"tests": [
    {"name": "r", "kind": "random", "count": 2,
     "ranges": {"distance": [60, 400], "v_cruise": [500, 3000], "max_clocks": 2e5}}]})");
  try {
    expand_list(never_fits, {}, {});
    FAIL() << "accepted";
  } catch (const scurve::input::Error& e) {
    expect_printable_line(e.what());
    EXPECT_EQ(std::string(e.what()).rfind("tests[0].ranges=", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("no plannable move of at most max_clocks in 100 draws"), std::string::npos)
        << e.what();
  }
  const nlohmann::json many = nlohmann::json::parse(R"({"tests": [
    {"name": "r", "kind": "random", "count": 300}]})");
  EXPECT_EQ(expand_list(many, {}, {}).size(), 300u);
  try {
    expand_list(many, {}, {}, 150);
    FAIL() << "accepted with a budget of 150 draws";
  } catch (const scurve::input::Error& e) {
    expect_printable_line(e.what());
    EXPECT_NE(std::string(e.what()).find("more than 150 planner draws in all"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sc
