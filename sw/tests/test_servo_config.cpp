// Controller settings in physical units -> register values, at a clock rate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "scurve/reg_encode.h"
#include "scurve/servo_config.h"

using namespace scurve;

TEST(ServoConfig, ControlPeriodAndSpeedsFollowTheClock) {
  for (double hz : {20e6, 25e6, 50e6}) {
    const ServoConfigResult r = to_servo_config(ControllerParams{}, 1.0, PulseTiming{}, Clock{hz});
    ASSERT_TRUE(std::holds_alternative<ServoConfig>(r)) << hz;
    const ServoConfig& c = std::get<ServoConfig>(r);
    EXPECT_EQ(c.ctl.div, uint16_t(hz / 10000)) << hz;  // 10 kHz control rate
    // v_lim 5000 pulses/s is 0.5 pulses per 100 us period at every clock.
    EXPECT_EQ(c.ctl.v_lim, uint32_t(0.5 * (1 << hw::CtlFrac))) << hz;
  }
}

TEST(ServoConfig, ControlRateOutOfRangeNamesTheBoundAtThisClock) {
  ControllerParams p;
  p.rate_hz = 100000;  // 250 clocks at 25 MHz: below the 256-clock minimum
  const ServoConfigResult r = to_servo_config(p, 1.0, PulseTiming{}, Clock{25e6});
  ASSERT_TRUE(std::holds_alternative<Error>(r));
  EXPECT_EQ(std::get<Error>(r).parameter, "rate_hz");
  EXPECT_NE(std::get<Error>(r).message.find("97656.25 Hz"), std::string::npos) << std::get<Error>(r).message;
  EXPECT_TRUE(std::holds_alternative<ServoConfig>(to_servo_config(p, 1.0, PulseTiming{}, Clock{50e6})));
}

// The defaults for a control rate keep the tuned loop's gains per second:
// the speed loop's K_v rate, the position integral weight's bound times the
// rate; K_p rate at and below 10 kHz, K_p per period above.
TEST(ServoConfig, DefaultsForARateKeepTheGainsPerSecond) {
  const ControllerParams tuned;
  const ControllerParams at10k = controller_defaults(kTunedControlRate);
  EXPECT_EQ(at10k.k_p, tuned.k_p);
  EXPECT_EQ(at10k.k_v, tuned.k_v);
  EXPECT_EQ(at10k.w_p1_max, tuned.w_p1_max);
  EXPECT_EQ(at10k.fixed_w_p1, tuned.fixed_w_p1);
  for (double rate : {305.2, 1000.0, 5000.0, 20000.0, 40000.0, 78125.0}) {
    const ControllerParams p = controller_defaults(rate);
    EXPECT_EQ(p.rate_hz, rate);
    EXPECT_DOUBLE_EQ(p.k_v * rate, tuned.k_v * kTunedControlRate) << rate;
    EXPECT_DOUBLE_EQ(p.w_p1_max * rate, tuned.w_p1_max * kTunedControlRate) << rate;
    EXPECT_DOUBLE_EQ(p.fixed_w_p1 * rate, tuned.fixed_w_p1 * kTunedControlRate) << rate;
    if (rate < kTunedControlRate) {
      EXPECT_DOUBLE_EQ(p.k_p * rate, tuned.k_p * kTunedControlRate) << rate;
    } else {
      EXPECT_EQ(p.k_p, tuned.k_p) << rate;
    }
    EXPECT_EQ(p.eta_p1, tuned.eta_p1);
    EXPECT_EQ(p.v_lim, tuned.v_lim);  // pulses/s: converted per period by to_servo_config
    EXPECT_TRUE(std::holds_alternative<ServoConfig>(to_servo_config(p, 1.0, PulseTiming{}))) << rate;
  }
}

TEST(ServoConfig, EncodedWordsCoverTheControllerWindow) {
  const ServoConfig c = std::get<ServoConfig>(to_servo_config(ControllerParams{}, 4.0, PulseTiming{}));
  const std::vector<RegWrite> w = encode_servo_config(c);
  ASSERT_EQ(int(w.size()), hw::ClCfgWords);
  for (int i = 0; i < hw::ClCfgWords; ++i) EXPECT_EQ(w[size_t(i)].addr, uint32_t(hw::RegClFirst + 4 * i));
  EXPECT_EQ(c.ctl.shift, 2);
}

TEST(RegEncode, UartFrameCarriesWordAddressDataAndCrc) {
  const FrameResult r = uart_write_frame(uint32_t(hw::RegCmd), 0x04030201u);
  ASSERT_TRUE(std::holds_alternative<std::vector<uint8_t>>(r));
  const std::vector<uint8_t>& f = std::get<std::vector<uint8_t>>(r);
  ASSERT_EQ(f.size(), 8u);
  EXPECT_EQ(f[0], hw::UartReqSync);
  EXPECT_EQ(f[1], hw::UartCmdWrite);
  EXPECT_EQ(f[2], hw::RegCmd / 4);  // word address
  EXPECT_EQ(f[3], 0x01);            // data little-endian
  EXPECT_EQ(f[6], 0x04);
  EXPECT_EQ(f[7], crc8(f.data() + 1, 6));
  EXPECT_EQ(reg_name(uint32_t(hw::RegCmd)), "CMD");
  // the last word of the 1 KiB window is address byte 0xFF
  const FrameResult last = uart_read_frame((1u << hw::RegAddrW) - 4);
  ASSERT_TRUE(std::holds_alternative<std::vector<uint8_t>>(last));
  EXPECT_EQ(std::get<std::vector<uint8_t>>(last).size(), 4u);
  EXPECT_EQ(std::get<std::vector<uint8_t>>(last)[2], 0xFF);
}

namespace {

std::string hex_addr(uint32_t a) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "addr=0x%X", unsigned(a));
  return buf;
}

}  // namespace

TEST(RegEncode, UartFrameRefusesUnalignedAndOutOfWindowAddresses) {
  for (const uint32_t a : {0x01u, 0x02u, 0x4Eu, 0x3FDu}) {
    const FrameResult r = uart_write_frame(a, 0);
    ASSERT_TRUE(std::holds_alternative<Error>(r)) << a;
    EXPECT_EQ(std::get<Error>(r).parameter, "addr");
    EXPECT_NE(std::get<Error>(r).message.find(hex_addr(a)), std::string::npos);
    EXPECT_NE(std::get<Error>(r).message.find("multiple of 4"), std::string::npos) << std::get<Error>(r).message;
  }
  for (const uint32_t a : {0x400u, 0x404u, 0xFFFFFFFCu}) {
    const FrameResult r = uart_read_frame(a);
    ASSERT_TRUE(std::holds_alternative<Error>(r)) << a;
    EXPECT_EQ(std::get<Error>(r).parameter, "addr");
    EXPECT_NE(std::get<Error>(r).message.find(hex_addr(a)), std::string::npos);
    EXPECT_NE(std::get<Error>(r).message.find("0x000..0x3FC"), std::string::npos) << std::get<Error>(r).message;
  }
}

TEST(RegEncode, MultiAxisMapFramesCarryTwoAddressBytesLowFirst) {
  ASSERT_EQ(uart_addr_bytes(hw::RegAddrW), 1);
  ASSERT_EQ(uart_addr_bytes(hw::MultiRegAddrW), 2);
  // axis 1's CMD: window 2
  const uint32_t addr = multi_axis_addr(size_t(1), uint32_t(hw::RegCmd));
  EXPECT_EQ(addr, (2u << hw::RegAddrW) | uint32_t(hw::RegCmd));
  const FrameResult r = uart_write_frame(addr, 0x04030201u, hw::MultiRegAddrW);
  ASSERT_TRUE(std::holds_alternative<std::vector<uint8_t>>(r));
  const std::vector<uint8_t>& f = std::get<std::vector<uint8_t>>(r);
  ASSERT_EQ(f.size(), 9u);
  EXPECT_EQ(f[1], hw::UartCmdWrite);
  EXPECT_EQ(f[2], uint8_t((addr / 4) & 0xFF));
  EXPECT_EQ(f[3], uint8_t((addr / 4) >> 8));
  EXPECT_EQ(f[4], 0x01);
  EXPECT_EQ(f[8], crc8(f.data() + 1, 7));
  EXPECT_EQ(std::get<std::vector<uint8_t>>(uart_read_frame(0, hw::MultiRegAddrW)).size(), 5u);
  // the group window is window 0
  EXPECT_EQ(multi_axis_addr(std::nullopt, uint32_t(hw::RegCtrl)), uint32_t(hw::RegCtrl));
  // beyond the multi-axis map, and a map width that does not exist
  const FrameResult beyond = uart_read_frame(1u << hw::MultiRegAddrW, hw::MultiRegAddrW);
  ASSERT_TRUE(std::holds_alternative<Error>(beyond));
  EXPECT_EQ(std::get<Error>(beyond).parameter, "addr");
  const FrameResult odd = uart_read_frame(0, 12);
  ASSERT_TRUE(std::holds_alternative<Error>(odd));
  EXPECT_EQ(std::get<Error>(odd).parameter, "addr_bits");
  EXPECT_NE(std::get<Error>(odd).message.find("addr_bits=12"), std::string::npos);
}

TEST(RegEncode, StopLimitsAreTheirRegistersInExecutorUnits) {
  const scurve::Clock clk{20e6};
  const auto r = scurve::encode_stop_limits(2e7, 2e5, clk);
  ASSERT_TRUE(std::holds_alternative<std::vector<scurve::RegWrite>>(r));
  const auto& w = std::get<std::vector<scurve::RegWrite>>(r);
  ASSERT_EQ(w.size(), 4u);
  EXPECT_EQ(w[0].addr, uint32_t(scurve::hw::RegStopJerk));
  EXPECT_EQ(w[2].addr, uint32_t(scurve::hw::RegStopAcc));
  // The register reset values are these limits at 20 MHz.
  EXPECT_EQ((uint64_t(w[1].data) << 32) | w[0].data, scurve::hw::StopJerkReset);
  EXPECT_EQ((uint64_t(w[3].data) << 32) | w[2].data, scurve::hw::StopAccReset);
}

TEST(RegEncode, GuardLimitsRoundUpToTheNextLsbAndWriteTheirRegisters) {
  const scurve::Clock clk{20e6};
  const auto r = scurve::guard_limit_codes(40000, 2e6, 4e8, clk);
  ASSERT_TRUE(std::holds_alternative<scurve::GuardLimitCodes>(r));
  const auto& c = std::get<scurve::GuardLimitCodes>(r);
  // Exact values: 40000 / 20e6 pulses per clock = 2^80 / 500 LSB, 2e6 / 20e6^2
  // = 2^80 / 2e8, 4e8 / 20e6^3 = 2^80 / 2e13; rounded up, by at most a
  // relative 2^-50 more.
  auto expect_up = [](scurve::u128 got, scurve::u128 num, scurve::u128 den, const char* what) {
    const scurve::u128 exact_up = (num + den - 1) / den;
    EXPECT_GE(got, exact_up) << what;
    EXPECT_LE(got, exact_up + (exact_up >> 49) + 1) << what;
  };
  expect_up(c.vel, scurve::kOne, 500, "velocity");
  expect_up(c.acc, scurve::kOne, 200'000'000, "acceleration");
  expect_up(c.jerk, scurve::kOne, 20'000'000'000'000, "jerk");
  const std::vector<scurve::RegWrite> w = scurve::encode_guard_codes(c);
  ASSERT_EQ(w.size(), 7u);
  EXPECT_EQ(w[0].addr, uint32_t(scurve::hw::RegGuardVel));
  EXPECT_EQ(w[3].addr, uint32_t(scurve::hw::RegGuardAcc));
  EXPECT_EQ(w[5].addr, uint32_t(scurve::hw::RegGuardJerk));
  EXPECT_EQ((scurve::u128(w[2].data) << 64) | (scurve::u128(w[1].data) << 32) | w[0].data, c.vel);
  EXPECT_EQ((uint64_t(w[4].data) << 32) | w[3].data, c.acc);
  EXPECT_EQ((uint64_t(w[6].data) << 32) | w[5].data, c.jerk);
  // A move's own limits: its largest speed, a_max and its jerk limit.
  scurve::MoveRequest m;
  m.distance = 1000;
  m.v_start = 50000;
  m.v_cruise = 40000;
  m.a_max = 2e6;
  m.j_max = 4e8;
  const auto mg = scurve::move_guard_codes(m, clk);
  ASSERT_TRUE(std::holds_alternative<scurve::GuardLimitCodes>(mg));
  expect_up(std::get<scurve::GuardLimitCodes>(mg).vel, scurve::kOne, 400, "the move's largest speed");
}

TEST(RegEncode, GuardLimitsOutOfRangeNameTheParameterAndTheBound) {
  for (const double bad : {0.0, -1.0, std::nan(""), 20e6, 1e30}) {
    const auto v = scurve::guard_limit_codes(bad, 2e6, 4e8);
    ASSERT_TRUE(std::holds_alternative<scurve::Error>(v)) << bad;
    EXPECT_EQ(std::get<scurve::Error>(v).parameter, "guard_v");
    EXPECT_NE(std::get<scurve::Error>(v).message.find("(0, 20000000)"), std::string::npos)
        << std::get<scurve::Error>(v).message;
    const auto a = scurve::guard_limit_codes(40000, bad == 20e6 ? 1e300 : bad, 4e8);
    ASSERT_TRUE(std::holds_alternative<scurve::Error>(a)) << bad;
    EXPECT_EQ(std::get<scurve::Error>(a).parameter, "guard_a");
    const auto j = scurve::guard_limit_codes(40000, 2e6, bad == 20e6 ? 1e300 : bad);
    ASSERT_TRUE(std::holds_alternative<scurve::Error>(j)) << bad;
    EXPECT_EQ(std::get<scurve::Error>(j).parameter, "guard_j");
  }
}

TEST(RegEncode, StopLimitsOutOfRangeNameTheParameterAndTheBound) {
  for (const double bad : {0.0, -1.0, std::nan(""), 1e30}) {
    const auto j = scurve::encode_stop_limits(bad, 2e5);
    ASSERT_TRUE(std::holds_alternative<scurve::Error>(j)) << bad;
    EXPECT_EQ(std::get<scurve::Error>(j).parameter, "stop_jerk");
    EXPECT_NE(std::get<scurve::Error>(j).message.find("needs a number in ["), std::string::npos);
    const auto a = scurve::encode_stop_limits(2e7, bad);
    ASSERT_TRUE(std::holds_alternative<scurve::Error>(a)) << bad;
    EXPECT_EQ(std::get<scurve::Error>(a).parameter, "stop_acc");
  }
}
