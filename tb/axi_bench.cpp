#include "axi_bench.h"

#include <fmt/format.h>

#include "reg_encode.h"

namespace sc {

std::string render(const AxiAxisOutputs& o) {
  return fmt::format(
      "awready={} wready={} bvalid={} bresp={} arready={} rvalid={} rdata=0x{:08x} rresp={} "
      "step={} dir={} en={} busy={} done={} fault={} phase={} pulse_count={} ref_pos={}",
      o.axi.awready, o.axi.wready, o.axi.bvalid, o.axi.bresp, o.axi.arready, o.axi.rvalid, o.axi.rdata,
      o.axi.rresp, o.step, o.dir, o.en, o.busy, o.done, o.fault, o.phase, o.pulse_count, o.ref_pos);
}

std::string render(const AxiServoOutputs& o) {
  return fmt::format(
      "awready={} wready={} bvalid={} bresp={} arready={} rvalid={} rdata=0x{:08x} rresp={} "
      "step={} dir={} en={} busy={} done={} fault={} phase={} pulse_count={} ref_pos={} enc_pos={} "
      "in_pos={} fault_ferr={}",
      o.axi.awready, o.axi.wready, o.axi.bvalid, o.axi.bresp, o.axi.arready, o.axi.rvalid, o.axi.rdata,
      o.axi.rresp, o.step, o.dir, o.en, o.busy, o.done, o.fault, o.phase, o.pulse_count, o.ref_pos, o.enc_pos,
      o.in_pos, o.fault_ferr);
}

AxiBench::AxiBench(bool with_rtl, uint32_t seed) : AxiMaster(seed) {
  if (with_rtl) rtl_ = std::make_unique<RtlAxiAxis>();
  reset();
}

void AxiBench::reset() {
  if (rtl_) rtl_->reset(4);
  model_.reset();
  in_ = AxiIn{};
  out_ = model_.outputs();
  last_step_ = out_.step;
}

void AxiBench::tick() {
  if (rtl_) rtl_->step(in_, side_);
  RegsSide ms = side_;
  ms.enc_pos = int32_t(uint32_t(ms.enc_pos) + uint32_t(model_enc_offset_));
  model_.step(in_, ms);
  const AxiAxisOutputs m = model_.outputs();
  out_ = rtl_ ? rtl_->outputs() : m;
  if (rtl_ && !(out_ == m) && error_.empty()) {
    error_ = fmt::format("clock {}: RTL and model differ\n  rtl:   {}\n  model: {}", clock_, render(out_), render(m));
  } else if (rtl_) {
    ++matched_;
  }
  if (model_.regs().state().start) {
    start_clock_ = clock_;
    rise_times_.clear();
  }
  if (out_.step && !last_step_) {
    net_steps_ += out_.dir ? 1 : -1;
    rise_times_.push_back(clock_ - start_clock_);
  }
  last_step_ = out_.step;
  ++clock_;
}

// ---- sc_axi_servo ------------------------------------------------------------------

AxiServoBench::AxiServoBench(bool with_rtl, uint32_t seed) : AxiMaster(seed) {
  if (with_rtl) rtl_ = std::make_unique<RtlAxiServo>();
  reset();
}

void AxiServoBench::reset() {
  if (rtl_) rtl_->reset(4);
  model_.reset();
  in_ = AxiIn{};
  out_ = model_.outputs();
  last_step_ = out_.step;
}

void AxiServoBench::tick() {
  if (plant_) side_.enc_ab = uint8_t((plant_->enc_a() ? 1 : 0) | (plant_->enc_b() ? 2 : 0));
  if (rtl_) rtl_->step(in_, side_);
  RegsSide ms = side_;
  if (inject_) ms.enc_ab ^= 1;
  model_.step(in_, ms);
  const AxiServoOutputs m = model_.outputs();
  out_ = rtl_ ? rtl_->outputs() : m;
  if (rtl_ && !(out_ == m) && error_.empty()) {
    error_ = fmt::format("clock {}: RTL and model differ\n  rtl:   {}\n  model: {}", clock_, render(out_), render(m));
  } else if (rtl_) {
    ++matched_;
  }
  if (out_.step && !last_step_) net_steps_ += out_.dir ? 1 : -1;
  last_step_ = out_.step;
  if (plant_) plant_->clock(out_.step, out_.dir);
  ++clock_;
}

int AxiMaster::delay() {
  if (!jitter_) return 0;
  return std::uniform_int_distribution<int>(0, 3)(rng_);
}

uint8_t AxiMaster::write(uint32_t addr, uint32_t data, uint8_t strb) {
  int aw_wait = delay(), w_wait = delay(), b_wait = delay();
  bool aw_done = false, w_done = false;
  in_.awaddr = uint8_t(addr);
  in_.wdata = data;
  in_.wstrb = strb;
  for (int guard = 0; guard < 1000 && !failed(); ++guard) {
    in_.awvalid = !aw_done && aw_wait <= 0;
    in_.wvalid = !w_done && w_wait <= 0;
    in_.bready = b_wait <= 0;
    const AxiOut o = axi_out();  // ready/valid during this clock
    const bool aw_hs = in_.awvalid && o.awready;
    const bool w_hs = in_.wvalid && o.wready;
    const bool b_hs = in_.bready && o.bvalid && aw_done && w_done;
    tick();
    --aw_wait;
    --w_wait;
    if (aw_done && w_done) --b_wait;
    aw_done = aw_done || aw_hs;
    w_done = w_done || w_hs;
    if (b_hs) {
      in_.awvalid = in_.wvalid = in_.bready = false;
      return o.bresp;
    }
  }
  if (error_.empty()) error_ = fmt::format("write 0x{:02x}: no response", addr);
  return 0xff;
}

std::pair<uint32_t, uint8_t> AxiMaster::read(uint32_t addr) {
  int ar_wait = delay(), r_wait = delay();
  bool ar_done = false;
  in_.araddr = uint8_t(addr);
  for (int guard = 0; guard < 1000 && !failed(); ++guard) {
    in_.arvalid = !ar_done && ar_wait <= 0;
    in_.rready = ar_done && r_wait <= 0;
    const AxiOut o = axi_out();
    const bool ar_hs = in_.arvalid && o.arready;
    const bool r_hs = in_.rready && o.rvalid;
    tick();
    --ar_wait;
    if (ar_done) --r_wait;
    ar_done = ar_done || ar_hs;
    if (r_hs) {
      in_.arvalid = in_.rready = false;
      return {o.rdata, o.rresp};
    }
  }
  if (error_.empty()) error_ = fmt::format("read 0x{:02x}: no response", addr);
  return {0, 0xff};
}

// ---- UART host ------------------------------------------------------------------

UartHost::UartHost(RtlBoard& board, int clks_per_bit) : b_(board), bit100_(5 * clks_per_bit) {}

void UartHost::tick() {
  b_.tick100(line_, true, estop, enc_ab & 1, (enc_ab >> 1) & 1);
  const RtlBoard::Pins p = b_.pins();
  if (p.step && !last_step_) {
    ++rises_;
    net_steps_ += p.dir ? 1 : -1;
  }
  last_step_ = p.step;
  // receiver: sample at the middle of each bit
  if (rx_state_ == 0) {
    if (!p.uart_tx) {
      rx_state_ = 1;
      rx_cnt_ = bit100_ / 2;
      rx_bit_ = -1;  // start bit
    }
  } else if (--rx_cnt_ <= 0) {
    rx_cnt_ = bit100_;
    if (rx_bit_ < 0) {
      if (p.uart_tx) rx_state_ = 0;  // glitch
      rx_bit_ = 0;
      rx_byte_ = 0;
    } else if (rx_bit_ < 8) {
      rx_byte_ = uint8_t(rx_byte_ | (p.uart_tx ? 1 : 0) << rx_bit_);
      ++rx_bit_;
    } else {
      if (p.uart_tx) rx_.push_back(rx_byte_);  // good stop bit
      rx_state_ = 0;
    }
  }
}

void UartHost::idle(uint64_t clocks100) {
  line_ = true;
  for (uint64_t i = 0; i < clocks100; ++i) tick();
}

std::vector<uint8_t> UartHost::transact(const std::vector<uint8_t>& frame, size_t expect, int timeout_bits) {
  rx_.clear();
  for (uint8_t byte : frame) {
    const int bits[10] = {0, byte & 1, byte >> 1 & 1, byte >> 2 & 1, byte >> 3 & 1,
                          byte >> 4 & 1, byte >> 5 & 1, byte >> 6 & 1, byte >> 7 & 1, 1};
    for (int b : bits) {
      line_ = b != 0;
      for (int i = 0; i < bit100_; ++i) tick();
    }
  }
  line_ = true;
  size_t have = rx_.size();
  int64_t quiet = 0;
  while (rx_.size() < expect && quiet < int64_t(timeout_bits) * bit100_) {
    tick();
    if (rx_.size() != have || rx_state_ != 0) {
      have = rx_.size();
      quiet = 0;
    } else {
      ++quiet;
    }
  }
  // let a last stop bit finish
  for (int i = 0; i < bit100_; ++i) tick();
  return rx_;
}

UartResponse UartHost::write(uint8_t addr, uint32_t data) {
  return parse_uart_response(transact(uart_write_frame(addr, data), 3), false);
}

UartResponse UartHost::read(uint8_t addr) {
  return parse_uart_response(transact(uart_read_frame(addr), 7), true);
}

}  // namespace sc
