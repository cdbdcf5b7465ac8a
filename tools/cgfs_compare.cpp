// cgfs-compare EXPECTED ACTUAL: is a student's image the chapter's figure?
// cgfs-compare --report FOLDER: the same for a whole folder laid out like out/,
// as one HTML page (tools/report.h).
//
// EXPECTED is an image file, or a figure named CHAPTER/FIGURE (for example
// 02-basic-rays/fig-2-11), which means tests/golden/CHAPTER/FIGURE.png.
// ACTUAL is the student's image, PNG or PPM (P6 or P3), from any language; a JPEG is
// read too, with a note that its compression changes pixels.
// Prints the numbers, writes a difference image, and exits 0 when the images
// match under the tolerance of the reference tests, 1 when they do not, and 2
// on bad input.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include <CLI/CLI.hpp>

#include "comparison/compare.h"
#include "program/arguments.h"
#include "program/error.h"
#include "program/image_files.h"
#include "report.h"

namespace fs = std::filesystem;

namespace {

// Every figure of the golden images, CHAPTER/FIGURE.
std::vector<std::string> AllFigures(const fs::path& golden) {
  std::vector<std::string> figures;
  std::error_code error;
  for (const auto& chapter : fs::directory_iterator(golden, error)) {
    for (const auto& entry : fs::directory_iterator(chapter.path(), error)) {
      if (entry.path().extension() == ".png") {
        figures.push_back((chapter.path().filename() / entry.path().stem()).string());
      }
    }
  }
  std::sort(figures.begin(), figures.end());
  return figures;
}

// What a figure name without its chapter (fig-2-11) was probably meant to be:
// " (a figure is CHAPTER/FIGURE: did you mean 02-basic-rays/fig-2-11?)", or empty.
std::string FigureSuggestion(const std::string& name, const fs::path& golden) {
  std::vector<std::string> figures = AllFigures(golden);
  std::vector<std::string> bare;
  for (const std::string& figure : figures) {
    bare.push_back(fs::path(figure).filename().string());
  }
  const std::string closest = cgfs::ClosestName(name, bare);
  if (closest.empty()) {
    return "";
  }
  const auto at = std::find(bare.begin(), bare.end(), closest);
  return " (a figure is CHAPTER/FIGURE: did you mean " + figures[at - bare.begin()] + "?)";
}

// The figures of one chapter's golden images.
std::vector<std::string> Stems(const fs::path& chapter) {
  std::vector<std::string> stems;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(chapter, error)) {
    if (entry.path().extension() == ".png") {
      stems.push_back(entry.path().stem().string());
    }
  }
  return stems;
}

std::string KnownFigures(const fs::path& golden, const fs::path& chapter) {
  std::string names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(golden / chapter, error)) {
    if (entry.path().extension() == ".png") {
      names += (names.empty() ? "" : ", ") + (chapter / entry.path().stem()).string();
    }
  }
  return names;
}

// Whether anything is at `path` (a broken link, a loop or an unreadable file
// counts: reading it then says what is wrong with it).
bool SomethingAt(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(path, error);
  if (error) {
    return error != std::errc::no_such_file_or_directory && error != std::errc::not_a_directory;
  }
  return status.type() != fs::file_type::not_found;
}

// A file, or CHAPTER/FIGURE among the golden images.
fs::path ResolveExpected(const std::string& argument, const fs::path& golden) {
  if (SomethingAt(argument)) {
    return argument;
  }
  const fs::path name(argument);
  const fs::path chapter = name.parent_path();
  if (name.has_extension() || chapter.empty() || chapter.has_parent_path()) {
    const bool bare = !name.has_extension() && chapter.empty();
    throw cgfs::Error("cannot read '" + argument + "': no such file" +
                      (bare ? FigureSuggestion(argument, golden) : ""));
  }
  std::error_code error;
  if (!fs::is_directory(golden, error)) {
    throw cgfs::Error("--golden '" + golden.string() + "' is not a folder we can read" +
                      (error ? ": " + error.message() : ""));
  }
  if (!fs::is_directory(golden / chapter, error)) {
    throw cgfs::Error("unknown chapter '" + chapter.string() + "' (no folder " +
                      (golden / chapter).string() + ")");
  }
  const fs::path file = golden / chapter / (name.filename().string() + ".png");
  if (!SomethingAt(file)) {
    const std::string closest =
        cgfs::ClosestName(name.filename().string(), Stems(golden / chapter));
    throw cgfs::Error(
        "unknown figure '" + argument + "'" +
        (closest.empty() ? "" : " (did you mean " + (chapter / closest).string() + "?)") +
        "; known: " + KnownFigures(golden, chapter));
  }
  return file;
}

// A golden image as the repository names it (tests/golden/02-basic-rays/fig-2-11.png),
// wherever the tool was run from; any other file as it was given.
std::string Shown(const fs::path& file, const fs::path& golden) {
  const fs::path ours(CGFS_GOLDEN_DIR);
  if (golden == ours && file.parent_path().parent_path() == ours) {
    return (fs::path("tests") / "golden" / file.parent_path().filename() / file.filename())
        .string();
  }
  return file.string();
}

// Whether `path` names something inside `folder`, however either is spelled (links,
// "..", relative or not).
bool Inside(const fs::path& path, const fs::path& folder) {
  std::error_code error;
  const fs::path where = fs::weakly_canonical(path, error);
  const fs::path within = fs::weakly_canonical(folder, error);
  if (error || within.empty()) {
    return false;
  }
  const auto [stop, rest] = std::mismatch(within.begin(), within.end(), where.begin(), where.end());
  return stop == within.end() && rest != where.end();
}

// Whether the name is one an image file of a report's folder may have.
bool ImageName(const fs::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return extension == ".png" || extension == ".ppm" || extension == ".jpg" || extension == ".jpeg";
}

// A file this run writes must not be one it reads: an image compared, a golden image,
// an image of the folder being reported on. Refused before anything is written.
void RefuseToOverwriteAnInput(const fs::path& destination, const std::string& option,
                              const std::vector<fs::path>& inputs, const fs::path& golden,
                              const fs::path& folder = {}) {
  if (Inside(destination, golden)) {
    throw cgfs::UsageError(option + " " + cgfs::Quoted(destination) +
                           " is in the folder of the golden images; nothing was written");
  }
  std::error_code error;
  bool input = !folder.empty() && Inside(destination, folder) && ImageName(destination) &&
               SomethingAt(destination);
  for (const fs::path& file : inputs) {
    input = input || fs::equivalent(destination, file, error);
  }
  // The same file as a golden image by device and inode, however it is reached (a link,
  // a bind mount of one of its folders).
  if (SomethingAt(destination)) {
    for (const auto& entry : fs::recursive_directory_iterator(golden, error)) {
      if (entry.is_regular_file(error) && fs::equivalent(destination, entry.path(), error)) {
        throw cgfs::UsageError(option + " " + cgfs::Quoted(destination) + " is the golden image " +
                               cgfs::Quoted(entry.path()) + "; nothing was written");
      }
    }
  }
  if (input) {
    throw cgfs::UsageError(option + " " + cgfs::Quoted(destination) +
                           " is one of the images this run reads; nothing was written");
  }
}

// --report: one page for a whole folder; exit 0 when every figure there passes.
// Whether the file starts as a JPEG does (FF D8 FF), whatever its name says.
bool IsJpeg(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  char start[3] = {};
  return in.read(start, 3) && start[0] == '\xff' && start[1] == '\xd8' && start[2] == '\xff';
}

int Report(const fs::path& folder, fs::path html, const fs::path& golden) {
  if (html.empty()) {
    html = folder / "report.html";
  }
  const std::vector<cgfs::ReportEntry> entries = cgfs::CompareFolder(folder, golden, true);
  const std::vector<std::string> unmatched = cgfs::UnmatchedNames(folder, golden);
  if (entries.empty()) {
    throw cgfs::Error(cgfs::Quoted(folder) +
                      " has no chapter folder (such as 02-basic-rays/) of ours" +
                      (unmatched.empty() ? "" : "; " + unmatched.front()));
  }
  std::vector<fs::path> inputs;
  for (const cgfs::ReportEntry& entry : entries) {
    inputs.push_back(entry.actual_file);
  }
  RefuseToOverwriteAnInput(html, "--html", inputs, golden, folder);
  cgfs::WriteReport(entries, html, "Your figures against ours: " + folder.string());
  int failed = 0;
  for (const cgfs::ReportEntry& entry : entries) {
    std::cout << entry.chapter << "/" << entry.figure << ": ";
    switch (entry.verdict) {
      case cgfs::ReportEntry::Verdict::kPassed:
        std::cout << "PASS";
        break;
      case cgfs::ReportEntry::Verdict::kFailed:
        std::cout << "FAIL";
        break;
      case cgfs::ReportEntry::Verdict::kMissing:
        std::cout << "missing";
        break;
      case cgfs::ReportEntry::Verdict::kUnreadable:
        std::cout << "unreadable";
        break;
    }
    if (entry.verdict != cgfs::ReportEntry::Verdict::kPassed) {
      ++failed;
    }
    if (!entry.diagnosis.empty()) {
      std::cout << " (" << entry.diagnosis << ")";
    }
    std::cout << "\n";
  }
  for (const std::string& note : unmatched) {
    std::cout << note << "\n";
  }
  std::cout << "report: " << html.string() << "\n";
  return failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return cgfs::RunReportingErrors("cgfs-compare", [&] {
    std::string expected_argument;
    std::string actual_argument;
    std::string difference_path;
    std::string golden = CGFS_GOLDEN_DIR;
    std::string report_folder;
    std::string html_path;
    CLI::App app(
        "Compares ACTUAL (PNG or PPM) with EXPECTED (an image, or a figure CHAPTER/FIGURE such as\n"
        "02-basic-rays/fig-2-11) under the reference tests' tolerance: a pixel differs when a\n"
        "channel is off by more than 2 levels, and at most 0.01% of the pixels may differ.\n"
        "With --report FOLDER, compares every CHAPTER/FIGURE.png or .ppm in FOLDER instead\n"
        "and writes one HTML page of them all.\n"
        "Exit status: 0 match, 1 no match, 2 bad input.",
        "cgfs-compare");
    auto* expected_option = app.add_option("EXPECTED", expected_argument,
                                           "the reference: CHAPTER/FIGURE or an image file");
    auto* actual_option = app.add_option("ACTUAL", actual_argument, "your image, PNG or PPM");
    auto* report_option =
        app.add_option("--report", report_folder,
                       "compare a folder laid out like out/ (CHAPTER/FIGURE.png) and write a page")
            ->type_name("FOLDER");
    report_option->excludes(expected_option)->excludes(actual_option);
    app.add_option("--html", html_path,
                   "where --report writes its page (default FOLDER/report.html)")
        ->type_name("FILE")
        ->needs(report_option);
    app.add_option("--diff", difference_path,
                   "where to write the difference image (default ACTUAL.diff.png)")
        ->type_name("FILE");
    app.add_option("--golden", golden, "folder of the golden images (default: this repo's)")
        ->type_name("DIR");
    if (!cgfs::ParseArguments(app, argc, argv)) {
      return 0;
    }
    if (!report_folder.empty()) {
      return Report(report_folder, html_path, golden);
    }
    if (expected_argument.empty() || actual_argument.empty()) {
      throw cgfs::UsageError("give EXPECTED and ACTUAL, or --report FOLDER");
    }

    const fs::path expected_file = ResolveExpected(expected_argument, golden);
    const fs::path actual_file = actual_argument;
    if (difference_path.empty()) {
      difference_path = (actual_file.parent_path() / actual_file.stem()).string() + ".diff.png";
    }
    RefuseToOverwriteAnInput(difference_path, "--diff", {actual_file, expected_file}, golden);

    const cgfs::Image expected = cgfs::ReadImage(expected_file);
    const cgfs::Image actual = cgfs::ReadImage(actual_file);
    const cgfs::Comparison comparison = cgfs::CompareImages(expected, actual);
    cgfs::WriteImage(comparison.difference, difference_path);

    std::cout << "expected: " << Shown(expected_file, golden) << "\n"
              << "actual:   " << actual_file.string() << "\n";
    if (IsJpeg(actual_file)) {
      std::cout << "note: ACTUAL is a JPEG, whose lossy compression changes pixels all over the\n"
                   "      image; write PNG or PPM to compare figures pixel for pixel\n";
    }
    std::cout << cgfs::Describe(comparison, actual.Width(), actual.Height())
              << "difference image: " << difference_path << " (" << cgfs::DifferenceLegend()
              << ")\n";
    return comparison.passed ? 0 : 1;
  });
}
