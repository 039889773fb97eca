#include "axi_bench.h"

#include <fmt/format.h>

#include <algorithm>

#include "reg_encode.h"

namespace sc {

namespace {

void add_axi(SignalValues& v, const AxiOut& a) {
  v.emplace_back("s_axi_awready_o", hex_bits(uint64_t(a.awready), 1));
  v.emplace_back("s_axi_wready_o", hex_bits(uint64_t(a.wready), 1));
  v.emplace_back("s_axi_bvalid_o", hex_bits(uint64_t(a.bvalid), 1));
  v.emplace_back("s_axi_bresp_o", hex_bits(uint64_t(a.bresp), 2));
  v.emplace_back("s_axi_arready_o", hex_bits(uint64_t(a.arready), 1));
  v.emplace_back("s_axi_rvalid_o", hex_bits(uint64_t(a.rvalid), 1));
  v.emplace_back("s_axi_rdata_o", hex_bits(uint64_t(a.rdata), 32));
  v.emplace_back("s_axi_rresp_o", hex_bits(uint64_t(a.rresp), 2));
}

template <class O>
void add_axis(SignalValues& v, const O& o) {
  v.emplace_back("step_o", hex_bits(uint64_t(o.step), 1));
  v.emplace_back("dir_o", hex_bits(uint64_t(o.dir), 1));
  v.emplace_back("en_o", hex_bits(uint64_t(o.en), 1));
  v.emplace_back("busy_o", hex_bits(uint64_t(o.busy), 1));
  v.emplace_back("done_o", hex_bits(uint64_t(o.done), 1));
  v.emplace_back("fault_o", hex_bits(uint64_t(o.fault), 1));
  v.emplace_back("phase_o", hex_bits(uint64_t(o.phase), PhaseW));
  v.emplace_back("pulse_count_o", hex_bits(int64_t(o.pulse_count), 32));
  v.emplace_back("ref_pos_o", hex_bits(int64_t(o.ref_pos), 32));
  v.emplace_back("irq_o", hex_bits(uint64_t(o.irq), 1));
}

}  // namespace

SignalValues render_signals(const AxiAxisOutputs& o) {
  SignalValues v;
  add_axi(v, o.axi);
  add_axis(v, o);
  return v;
}

SignalValues render_signals(const AxiServoOutputs& o) {
  SignalValues v;
  add_axi(v, o.axi);
  add_axis(v, o);
  v.emplace_back("enc_pos_o", hex_bits(int64_t(o.enc_pos), 32));
  v.emplace_back("in_pos_o", hex_bits(uint64_t(o.in_pos), 1));
  v.emplace_back("fault_ferr_o", hex_bits(uint64_t(o.fault_ferr), 1));
  return v;
}

SignalValues render_signals(const AxiMultiAxisOutputs& o) {
  SignalValues v;
  add_axi(v, o.axi);
  for (size_t a = 0; a < o.axes; ++a) {
    const AxiMultiAxisOutputs::Axis& x = o.axis[a];
    auto put = [&](const char* name, std::string value) { v.emplace_back(fmt::format("{}[{}]", name, a), value); };
    put("step_o", hex_bits(uint64_t(x.step), 1));
    put("dir_o", hex_bits(uint64_t(x.dir), 1));
    put("en_o", hex_bits(uint64_t(x.en), 1));
    put("busy_o", hex_bits(uint64_t(x.busy), 1));
    put("done_o", hex_bits(uint64_t(x.done), 1));
    put("fault_o", hex_bits(uint64_t(x.fault), 1));
    put("phase_o", hex_bits(uint64_t(x.phase), PhaseW));
    put("pulse_count_o", hex_bits(int64_t(x.pulse_count), 32));
    put("ref_pos_o", hex_bits(int64_t(x.ref_pos), 32));
    put("enc_pos_o", hex_bits(int64_t(x.enc_pos), 32));
    put("in_pos_o", hex_bits(uint64_t(x.in_pos), 1));
    put("fault_ferr_o", hex_bits(uint64_t(x.fault_ferr), 1));
  }
  v.emplace_back("irq_o", hex_bits(uint64_t(o.irq), 1));
  return v;
}

void AxiMaster::note(const LockstepLog& checker, const PinMonitor& pins) {
  if (!error_.empty()) [[likely]] return;
  if (!checker.errors().empty()) {
    error_ = checker.errors().front().to_string();
  } else if (!pins.errors().empty()) {
    error_ = "pins: " + pins.errors().front();
  }
}

AxiBench::AxiBench(bool with_rtl, uint32_t seed) : AxiLockstepBench(with_rtl, seed, StepAccounting::ReferencePosition) {
  reset();
}

void AxiBench::reset() {
  AxiLockstepBench::reset();
  last_step_ = out_.step;
}

void AxiBench::tick() {
  if (switch_pins_) side_.sw_pins = switch_pins_(pins_.net_steps());
  if (encoder_) {
    const Encoder e = encoder_(pins_.net_steps());
    side_.enc_pos = e.count;
    side_.enc_z = e.index;
  }
  if (rtl_) rtl_->step(in_, side_);
  RegsSide ms = side_;
  ms.enc_pos = int32_t(uint32_t(ms.enc_pos) + uint32_t(model_enc_offset_));
  model_.step(in_, ms);
  const AxiAxisOutputs m = model_.outputs();
  out_ = rtl_ ? rtl_->outputs() : m;
  if (rtl_) checker_.compare(clock_, out_, m);
  if (model_.regs().state().start) {
    start_clock_ = clock_;
    rise_times_.clear();
    pins_.set_timing(model_.regs().state().cfg);  // as programmed for this move
  }
  pins_.on_clock(clock_, out_.step, out_.dir, out_.done, out_.phase, out_.ref_pos,
                 model_.core().step_gen().state().pend);
  if (out_.step && !last_step_) rise_times_.push_back(clock_ - start_clock_);
  last_step_ = out_.step;
  note(checker_, pins_);
  ++clock_;
}

// ---- sc_axi_servo ------------------------------------------------------------------

AxiServoBench::AxiServoBench(bool with_rtl, uint32_t seed)
    : AxiLockstepBench(with_rtl, seed, StepAccounting::PulseCounter) {
  reset();
}

void AxiServoBench::tick() {
  if (plant_) {
    side_.enc_ab = uint8_t((plant_->enc_a() ? 1 : 0) | (plant_->enc_b() ? 2 : 0));
    side_.enc_z = plant_->enc_z();
  }
  if (rtl_) rtl_->step(in_, side_);
  RegsSide ms = side_;
  if (inject_) ms.enc_ab ^= 1;
  model_.step(in_, ms);
  const AxiServoOutputs m = model_.outputs();
  out_ = rtl_ ? rtl_->outputs() : m;
  if (rtl_) checker_.compare(clock_, out_, m);
  if (model_.regs().state().start) pins_.set_timing(model_.regs().state().cfg);  // as programmed for this move
  pins_.on_clock(clock_, out_.step, out_.dir, out_.done, out_.phase, out_.pulse_count);
  note(checker_, pins_);
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
  in_.awaddr = uint16_t(addr & addr_mask_);  // the bus has this many address wires
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
  if (error_.empty()) error_ = fmt::format("write 0x{:03x}: no response", addr);
  return 0xff;
}

std::pair<uint32_t, uint8_t> AxiMaster::read(uint32_t addr) {
  int ar_wait = delay(), r_wait = delay();
  bool ar_done = false;
  in_.araddr = uint16_t(addr & addr_mask_);
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
  if (error_.empty()) error_ = fmt::format("read 0x{:03x}: no response", addr);
  return {0, 0xff};
}

// ---- UART host ------------------------------------------------------------------

namespace {

// A pulse timing in pin clocks (5 per system clock).
PulseTiming pin_timing(const PulseTiming& t) {
  auto pin_clocks = [](uint16_t v) { return uint16_t(std::min(5 * uint32_t(v), uint32_t(UINT16_MAX))); };
  return PulseTiming{pin_clocks(t.high), pin_clocks(t.low), pin_clocks(t.setup), pin_clocks(t.hold)};
}

}  // namespace

UartHost::UartHost(RtlBoard& board, int clks_per_bit) : BoardUartHost(clks_per_bit, RegAddrW), b_(board) {
  set_timing(PulseTiming{});
}

void UartHost::set_timing(const PulseTiming& t) { pins_.set_timing(pin_timing(t)); }

void UartHost::tick() {
  b_.tick100(line_.tx_level(), true, estop, enc_ab & 1, (enc_ab >> 1) & 1, 0, enc_z);
  const RtlBoard::Pins p = b_.pins();
  pins_.on_clock(b_.clocks100(), p.step, p.dir, false, 0);
  line_.clock(p.uart_tx);
}

UartHostXY::UartHostXY(RtlBoardXY& board, int clks_per_bit)
    : BoardUartHost(clks_per_bit, MultiRegAddrW), b_(board) {
  for (size_t a = 0; a < RtlBoardXY::kAxes; ++a) {
    pins_.emplace_back(PinRules{pin_timing(PulseTiming{}), false, StepAccounting::None});
  }
}

void UartHostXY::tick() {
  b_.tick100(line_.tx_level());
  const RtlBoardXY::Pins p = b_.pins();
  for (size_t a = 0; a < RtlBoardXY::kAxes; ++a) pins_[a].on_clock(b_.clocks100(), p.step[a], p.dir[a], false, 0);
  line_.clock(p.uart_tx);
}

void BoardUartHost::idle(uint64_t clocks100) {
  for (uint64_t i = 0; i < clocks100; ++i) tick();
}

std::vector<uint8_t> BoardUartHost::transact(const std::vector<uint8_t>& frame, size_t expect, int timeout_bits) {
  (void)line_.take_received();
  for (uint8_t byte : frame) line_.send(byte);
  while (line_.sending()) tick();
  size_t have = line_.received_count();
  int64_t quiet = 0;
  while (line_.received_count() < expect && quiet < int64_t(timeout_bits) * bit100_) {
    tick();
    if (line_.received_count() != have || line_.receiving()) {
      have = line_.received_count();
      quiet = 0;
    } else {
      ++quiet;
    }
  }
  // let a last stop bit finish
  for (int i = 0; i < bit100_; ++i) tick();
  return line_.take_received();
}

namespace {

UartResponse refused(const scurve::Error& e) {
  UartResponse r;
  r.error = e.message;
  return r;
}

}  // namespace

UartResponse BoardUartHost::write(uint32_t addr, uint32_t data) {
  const scurve::FrameResult f = uart_write_frame(addr, data, addr_bits_);
  if (const auto* e = std::get_if<scurve::Error>(&f)) return refused(*e);
  return parse_uart_response(transact(std::get<std::vector<uint8_t>>(f), 3), false);
}

UartResponse BoardUartHost::read(uint32_t addr) {
  const scurve::FrameResult f = uart_read_frame(addr, addr_bits_);
  if (const auto* e = std::get_if<scurve::Error>(&f)) return refused(*e);
  return parse_uart_response(transact(std::get<std::vector<uint8_t>>(f), 7), true);
}

AxiMultiBench::AxiMultiBench(bool with_rtl, uint32_t seed)
    : AxiMaster(seed), model_(RtlAxiMultiAxis::kAxes, RtlAxiMultiAxis::kServo) {
  addr_mask_ = (1u << MultiRegAddrW) - 1;
  if (with_rtl) rtl_ = std::make_unique<RtlAxiMultiAxis>();
  for (size_t a = 0; a < RtlAxiMultiAxis::kAxes; ++a) {
    monitors_.emplace_back(PinRules{PulseTiming{}, false, StepAccounting::PulseCounter});
  }
  reset();
}

void AxiMultiBench::reset() {
  if (rtl_) rtl_->reset(4);
  model_.reset();
  in_ = AxiIn{};
  out_ = model_.outputs();
  busy_.fill(false);
}

void AxiMultiBench::attach_plants(const PlantConfig& cfg) {
  plants_.clear();
  for (size_t a = 0; a < RtlAxiMultiAxis::kAxes; ++a) plants_.push_back(std::make_unique<Plant>(cfg, double(ClkHz)));
}

void AxiMultiBench::tick() {
  for (size_t a = 0; a < plants_.size(); ++a) {
    pins_in_[a].enc_a = plants_[a]->enc_a();
    pins_in_[a].enc_b = plants_[a]->enc_b();
    pins_in_[a].enc_z = plants_[a]->enc_z();
  }
  if (rtl_) rtl_->step(in_, estop, pins_in_);
  model_.step(in_, estop, pins_in_);
  const AxiMultiAxisOutputs m = model_.outputs();
  out_ = rtl_ ? rtl_->outputs() : m;
  if (rtl_) checker_.compare(clock_, out_, m);
  bool any_rose = false, all_rose = true;
  for (size_t a = 0; a < out_.axes; ++a) {
    const AxiMultiAxisOutputs::Axis& x = out_.axis[a];
    if (model_.regs(a).state().start) monitors_[a].set_timing(model_.regs(a).state().cfg);
    monitors_[a].on_clock(clock_, x.step, x.dir, x.done, x.phase, x.pulse_count);
    note(checker_, monitors_[a]);
    const bool rose = x.busy && !busy_[a];
    any_rose = any_rose || rose;
    all_rose = all_rose && rose;
    busy_[a] = x.busy;
  }
  // One START for all: every axis's STATUS.BUSY rises on the same clock (it
  // falls when the axis's own last pulse has left, which its timing decides).
  if (any_rose && !all_rose && error_.empty()) {
    error_ = fmt::format("clock {}: STATUS.BUSY rose on some axes only", clock_);
  }
  for (size_t a = 0; a < plants_.size(); ++a) plants_[a]->clock(out_.axis[a].step, out_.axis[a].dir);
  ++clock_;
}

}  // namespace sc
