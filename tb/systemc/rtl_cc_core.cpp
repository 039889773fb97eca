// The Verilated --cc RTL as a bench Core (C++20 side; kept apart so the
// pin-accurate bench, which has its own --sc runtime, never links it).
#include "components.h"
#include "rtl_core.h"

namespace sc::bench {

namespace {

class RtlCcCore : public Core {
 public:
  RtlCcCore(const std::string& fst, uint64_t from, uint64_t to) {
    if (!fst.empty()) rtl_.trace_open(fst, from, to);
  }
  void close_outputs() override { rtl_.trace_close(); }
  void reset(int cycles) override { rtl_.reset(cycles); }
  void step(const CoreInputs& in) override {
    rtl_.step(in);
    rtl_.read_outputs(out_);
  }
  void tick() override {
    rtl_.tick();
    rtl_.read_outputs(out_);
  }
  const CoreOutputs& outputs() const override { return out_; }
  bool done() const override { return out_.done; }
  uint32_t phase() const override { return out_.phase; }
  int32_t pulse_count() const override { return out_.pulse_count; }

 private:
  RtlCore rtl_;
  CoreOutputs out_{};
};

}  // namespace

std::unique_ptr<Core> make_rtl_cc_core(const std::string& fst_path, uint64_t fst_from, uint64_t fst_to) {
  return std::make_unique<RtlCcCore>(fst_path, fst_from, fst_to);
}

}  // namespace sc::bench
