#pragma once
// Each subcommand lives in its own file and registers itself on the app;
// main.cpp only wires them together and turns errors into exit codes.
#include <CLI/CLI.hpp>
#include <string>

namespace meshparticles {

// --device P:D|NAME, shared by every command that uses a device.
void add_device_option(CLI::App& command, std::string& device_request);

void add_info_command(CLI::App& app);
void add_devices_command(CLI::App& app);
void add_generate_command(CLI::App& app);

}  // namespace meshparticles
