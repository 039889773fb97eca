#include "scurve/cli/host_commands.h"

#include <iostream>

#include "scurve/cli/board_cli.h"
#include "scurve/cli/move_flags.h"
#include "scurve/cli/plan_report.h"
#include "scurve/cli/regs_cli.h"

namespace scurve::cli {

namespace {

class HostCommandsImpl : public HostCommands {
 public:
  explicit HostCommandsImpl(CLI::App& app) {
    plan_cmd_ = app.add_subcommand("plan", "plan a move and print its segment table");
    add_move_flags(plan_cmd_, pf_);
    add_clock_flag(plan_cmd_, pf_);
    add_output_flags(plan_cmd_, pf_);

    regs_cmd_ = app.add_subcommand("regs", "plan a move and print it as register writes (AXI4-Lite, --uart frames)");
    add_move_flags(regs_cmd_, rf_);
    add_clock_flag(regs_cmd_, rf_);
    add_output_flags(regs_cmd_, rf_);
    add_regs_flags(regs_cmd_, regs_flags_);

    board_ = add_board_command(app);
  }

  bool run(int* rc) const override {
    if (*plan_cmd_) {
      *rc = run_plan();
      return true;
    }
    if (*regs_cmd_) {
      *rc = run_regs();
      return true;
    }
    return board_->run(rc);
  }

 private:
  int run_plan() const {
    const auto r = plan_flags(pf_);
    if (const auto* e = std::get_if<Error>(&r)) return bad_input(e->message);
    const Plan& p = std::get<Plan>(r);
    const MoveRequest request = to_request(pf_);
    const nlohmann::json j = plan_to_json(p, request);
    if (pf_.json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << plan_to_table(p, request);
    }
    if (!write_json_file(pf_.json_out, j)) return bad_input("--json-out: cannot write " + pf_.json_out);
    return 0;
  }

  int run_regs() const {
    const auto r = plan_flags(rf_);
    if (const auto* e = std::get_if<Error>(&r)) return bad_input(e->message);
    return run_regs_cli(regs_flags_, to_request(rf_), std::get<Plan>(r), to_timing(rf_), rf_.json, rf_.json_out);
  }

  CLI::App* plan_cmd_ = nullptr;
  CLI::App* regs_cmd_ = nullptr;
  MoveFlags pf_, rf_;
  RegsCliFlags regs_flags_;
  std::unique_ptr<BoardCommand> board_;
};

}  // namespace

std::unique_ptr<HostCommands> add_host_commands(CLI::App& app) { return std::make_unique<HostCommandsImpl>(app); }

}  // namespace scurve::cli
