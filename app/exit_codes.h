#pragma once

namespace sedem::app::exit_code {

// The process exit status of every command (also in README.md).
inline constexpr int ok = 0;
inline constexpr int usage = 1;              // bad command line
inline constexpr int invalid_scene = 2;      // scene file missing, unreadable or invalid
inline constexpr int output_unwritable = 3;  // output folder cannot be written, or is taken
inline constexpr int io_failure = 4;         // writing failed during the run (disk full, ...)
inline constexpr int engine_failure = 5;     // the simulation failed (instability, crash)
inline constexpr int interrupted = 130;      // stopped by Ctrl-C or SIGTERM

}  // namespace sedem::app::exit_code
