#pragma once
// Subcommands of the `dockgrammar` program; each file tools/dockgrammar/<name>_command.cpp
// registers one of them on the top-level CLI11 app.

#include <CLI/CLI.hpp>

namespace dg::cli {

void add_info_command(CLI::App& app);
void add_analyze_command(CLI::App& app);
void add_symmetry_command(CLI::App& app);
void add_resize_command(CLI::App& app);
void add_generate_command(CLI::App& app);
void add_lsystem_command(CLI::App& app);
void add_lsystem_infer_subcommand(CLI::App& lsystem);
void add_verify_command(CLI::App& app);
void add_grow_command(CLI::App& app);

}  // namespace dg::cli
