// The visual report: one self-contained HTML page with, per figure, our image,
// yours and their difference, the numbers, the verdict and the diagnosis.
// Written by `cgfs-compare --report FOLDER` and by the golden tests on failure.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "cgfs/image.h"
#include "comparison/compare.h"

namespace cgfs {

struct ReportEntry {
  enum class Verdict { kPassed, kFailed, kMissing, kUnreadable };
  std::string chapter;
  std::string figure;
  Verdict verdict = Verdict::kMissing;
  std::filesystem::path actual_file;  // empty when missing
  std::string message;                // the numbers, or why the file could not be used
                                      // (without the diagnosis, which has its own line)
  std::string diagnosis;
  Image expected, actual, difference;  // actual and difference empty unless compared
};

// Compares every image of FOLDER laid out like out/ (<chapter>/<figure>.png or
// .ppm) with the golden image of that name. With list_missing, every figure of a
// chapter folder present in FOLDER that has no image is listed as missing.
std::vector<ReportEntry> CompareFolder(const std::filesystem::path& folder,
                                       const std::filesystem::path& golden, bool list_missing);

// One line per folder or image in FOLDER whose name is not one of ours, so it
// was not compared, with the name it was probably meant to have: "03-light/
// fig-3-16.png: not one of our figures, not compared (did you mean
// fig-3-16-specular?)".
std::vector<std::string> UnmatchedNames(const std::filesystem::path& folder,
                                        const std::filesystem::path& golden);

// The one of `names` that `name` was most likely meant to be: one that starts with it
// or it starts with (fig-3-16 for fig-3-16-specular), else the closest within three
// edits; empty when none is close.
std::string ClosestName(const std::string& name, const std::vector<std::string>& names);

// Writes the page (images embedded as data: URLs), replacing `html` only by a
// complete new file. Throws cgfs::Error.
void WriteReport(const std::vector<ReportEntry>& entries, const std::filesystem::path& html,
                 const std::string& title);

}  // namespace cgfs
