#include "model_fst.h"

#include <fmt/format.h>

#include <stdexcept>

#include "fstapi.h"

namespace sc {

namespace {

struct Port {
  const char* name;
  int bits;
};
// sc_axis_core's outputs, in CoreOutputs order (rtl/sc_axis_core.sv).
const Port kPorts[] = {
    {"step_o", 1},          {"dir_o", 1},           {"en_o", 1},           {"busy_o", 1},
    {"done_o", 1},          {"phase_o", PhaseW},    {"fault_table_o", 1},  {"fault_overrun_o", 1},
    {"pulse_count_o", PosIntW}, {"ref_pos_int_o", PosIntW}, {"ref_pos_frac_o", FracBits}, {"ref_vel_o", VelW},
    {"ref_acc_o", AccW},    {"ref_jerk_o", JerkW},  {"seg_idx_o", SegIdxW}, {"step_pending_o", PendW},
};

std::string bits_of(u128 v, int n) {
  std::string s(size_t(n), '0');
  for (int i = 0; i < n; ++i) s[size_t(n - 1 - i)] = ((v >> i) & 1) ? '1' : '0';
  return s;
}

std::vector<std::string> values(const CoreOutputs& o) {
  return {bits_of(o.step, 1),
          bits_of(o.dir, 1),
          bits_of(o.en, 1),
          bits_of(o.busy, 1),
          bits_of(o.done, 1),
          bits_of(o.phase, PhaseW),
          bits_of(o.fault_table, 1),
          bits_of(o.fault_overrun, 1),
          bits_of(u128(uint32_t(o.pulse_count)), PosIntW),
          bits_of(u128(uint32_t(o.ref_pos_int)), PosIntW),
          bits_of(o.ref_pos_frac, FracBits),
          bits_of(u128(o.ref_vel), VelW),
          bits_of(u128(i128(o.ref_acc)), AccW),
          bits_of(u128(i128(o.ref_jerk)), JerkW),
          bits_of(o.seg_idx, SegIdxW),
          bits_of(u128(uint8_t(o.step_pending)), PendW)};
}

}  // namespace

ModelFstWriter::ModelFstWriter(const std::string& param, const std::string& path, uint64_t from, uint64_t to)
    : out_(std::make_unique<FstOutput>(param, path)), from_(from), to_(to) {
  ctx_ = fstWriterCreate(out_->part_path().c_str(), 1);
  if (!ctx_) out_->creation_failed();
  fstWriterSetTimescale(ctx_, -9);  // ns, as tb/rtl_core.cpp: 50 per 20 MHz clock
  fstWriterSetScope(ctx_, FST_ST_VCD_MODULE, "sc_axis_core", nullptr);
  for (const Port& p : kPorts) {
    const std::string name = p.bits > 1 ? fmt::format("{} [{}:0]", p.name, p.bits - 1) : p.name;
    handles_.push_back(fstWriterCreateVar(ctx_, FST_VT_VCD_WIRE, FST_VD_OUTPUT, uint32_t(p.bits), name.c_str(), 0));
  }
  fstWriterSetUpscope(ctx_);
}

ModelFstWriter::~ModelFstWriter() {
  if (ctx_) fstWriterClose(ctx_);  // not committed: out_ removes the file
}

void ModelFstWriter::write(uint64_t clock, const CoreOutputs& o) {
  const std::vector<std::string> v = values(o);
  bool time_set = false;
  for (size_t i = 0; i < v.size(); ++i) {
    if (!first_ && v[i] == last_[i]) continue;
    if (!time_set) {
      fstWriterEmitTimeChange(ctx_, clock * 50);
      time_set = true;
    }
    fstWriterEmitValueChange(ctx_, handles_[i], v[i].c_str());
  }
  last_ = v;
  first_ = false;
}

void ModelFstWriter::close(uint64_t end_clock) {
  if (!ctx_) return;
  // Mark the end like the RTL trace's last (falling-edge) dump of the window.
  const uint64_t end = std::min(end_clock, to_);
  if (!first_ && end != UINT64_MAX && end > from_) fstWriterEmitTimeChange(ctx_, (end - 1) * 50 + 25);
  fstWriterClose(ctx_);
  ctx_ = nullptr;
  out_->commit();
}

}  // namespace sc
