#pragma once

#include "apcs/cli/export_command.h"
#include "inbetween_command.h"
#include "apcs/cli/options.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace apcs {

class PlainOptionFormatter : public CLI::Formatter {
public:
    PlainOptionFormatter()
    {
        label("SUBCOMMAND", "COMMAND");
        label("Positionals", "Arguments");
    }
    std::string make_option_opts(const CLI::Option* option) const override;
};

// Each command takes only the options it uses (manual section 14): an option of another command
// is a usage error, never silently ignored. `slopes` collects --slopes S0 S1 for all of them.
void add_session_options(CLI::App& app, CommonOptions& options, std::vector<double>& slopes);
// The session's options that shape what its keys do, which a key script's OPTIONS line may carry
// (script_options.h): the staff's start, the curve, the surface, the in-betweens, the view, the
// delay and the staff step. The others choose how it looks and where pictures go.
void add_carried_options(CLI::App& app, CommonOptions& options, std::vector<double>& slopes);
void add_path_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes);
void add_fit_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes);
void add_inbetween_command_options(CLI::App& command, CommonOptions& options, InbetweenSettings& settings);
void add_export_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes,
                                ExportRequest& request);
void add_draw_command_options(CLI::App& command, CommonOptions& options);
void add_play_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes, bool& tree);
void add_figures_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes);

} // namespace apcs
