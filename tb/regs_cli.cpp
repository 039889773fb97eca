#include "regs_cli.h"

#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "closed_loop_run.h"
#include "reg_encode.h"

namespace sc {

void add_regs_flags(CLI::App* cmd, RegsCliFlags& f) {
  cmd->add_flag("--uart", f.uart, "print the UART bridge frames (hex bytes, CRC-8) instead of address = data");
  cmd->add_flag("--no-start", f.no_start, "leave out the final CMD.START write");
  cmd->add_flag("--closed-loop", f.closed_loop,
                "closed-loop axis (board top): write the controller settings (the closed-loop runner's "
                "defaults for this pulse timing) and CTRL.CLOSED_LOOP before the table");
}

int run_regs_cli(const RegsCliFlags& f, const Plan& plan, const PulseTiming& timing, bool json) {
  std::vector<RegWrite> writes = encode_move(plan, timing, !f.no_start);
  if (f.closed_loop) {
    ServoConfig cfg;
    if (const std::string err = to_servo_config(ControllerParams{}, PlantConfig{}, timing, cfg); !err.empty()) {
      std::cerr << "scurve regs --closed-loop: " << err << "\n";
      return 2;
    }
    std::vector<RegWrite> cl = encode_servo_config(cfg);
    cl.insert(cl.begin(), RegWrite{uint32_t(RegCtrl), (1u << CtrlEnableBit) | (1u << CtrlClosedBit)});
    writes.erase(writes.begin());  // CTRL = enable: replaced by the closed-loop CTRL write
    writes.insert(writes.begin(), cl.begin(), cl.end());
  }
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const RegWrite& w : writes) {
      nlohmann::json j = {{"addr", w.addr}, {"reg", reg_name(w.addr)}, {"data", w.data}};
      if (f.uart) {
        std::string hex;
        for (uint8_t b : uart_write_frame(uint8_t(w.addr), w.data)) hex += fmt::format("{:02X}", b);
        j["frame"] = hex;
      }
      out.push_back(j);
    }
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  for (const RegWrite& w : writes) {
    if (f.uart) {
      std::string hex;
      for (uint8_t b : uart_write_frame(uint8_t(w.addr), w.data)) hex += fmt::format("{:02X} ", b);
      std::cout << fmt::format("{} # {} = 0x{:08X}\n", hex, reg_name(w.addr), w.data);
    } else {
      std::cout << fmt::format("0x{:02X} {:<12} 0x{:08X}\n", w.addr, reg_name(w.addr), w.data);
    }
  }
  return 0;
}

}  // namespace sc
