#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace sedem::app {

// The page's name in a run folder.
inline constexpr const char* kRunReport = "report.html";

// report.html: a run folder as one page that opens from the folder with no server. From the
// run's record (run.json's content, its "files" what the folder holds): the status (a run that
// did not complete is marked "partial", with why), version, wall and simulated time, each
// test's error and bias ("-" and the record's note where there is none), every figure (SVG
// with the PNG as fallback), the frames as a player and a strip, links to the CSVs, the
// ParaView series and run.json, and the scene as resolved. Every text from the record is
// escaped; every link is relative. `dir` is named in the way on for an interrupted run.
std::string run_report_html(const nlohmann::json& record, const std::filesystem::path& dir);

// Writes dir/report.html (atomically) from `record`; the page lists itself among the files.
void write_run_report(nlohmann::json record, const std::filesystem::path& dir);

}  // namespace sedem::app
