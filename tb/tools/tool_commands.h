// The `scurve diff` and `scurve regress` subcommands, kept out of
// scurve_main.cpp: main adds them with add_tool_commands() and, after
// parsing, lets run_tool_command() handle them.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>

namespace sc {

struct ToolCommands;  // options of both subcommands
std::shared_ptr<ToolCommands> add_tool_commands(CLI::App& app);
// True when one of the tool subcommands was given; *exit_code is then set.
bool run_tool_command(const ToolCommands& tools, int* exit_code);

}  // namespace sc
