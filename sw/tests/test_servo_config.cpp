// Controller settings in physical units -> register values, at a clock rate.
#include <gtest/gtest.h>

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

TEST(ServoConfig, EncodedWordsCoverTheControllerWindow) {
  const ServoConfig c = std::get<ServoConfig>(to_servo_config(ControllerParams{}, 4.0, PulseTiming{}));
  const std::vector<RegWrite> w = encode_servo_config(c);
  ASSERT_EQ(int(w.size()), hw::ClCfgWords);
  for (int i = 0; i < hw::ClCfgWords; ++i) EXPECT_EQ(w[size_t(i)].addr, uint32_t(hw::RegClFirst + 4 * i));
  EXPECT_EQ(c.ctl.shift, 2);
}

TEST(RegEncode, UartFrameCarriesAddressDataAndCrc) {
  const std::vector<uint8_t> f = uart_write_frame(0x08, 1);
  ASSERT_EQ(f.size(), 8u);
  EXPECT_EQ(f[0], hw::UartReqSync);
  EXPECT_EQ(f[7], crc8(f.data() + 1, 6));
  EXPECT_EQ(reg_name(uint32_t(hw::RegCmd)), "CMD");
}
