#pragma once
// The program's version, from CMake's project(VERSION): one place for
// `meshparticles --version`, report.json and the batch summary.
#include <string>

namespace meshparticles {

const std::string& program_version();

}  // namespace meshparticles
