#include "report.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <sstream>
#include <system_error>
#include <utility>

#include "program/error.h"
#include "program/image_files.h"
#include "program/safe_file.h"

namespace cgfs {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> SortedEntries(const fs::path& folder) {
  std::vector<fs::path> entries;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    entries.push_back(entry.path());
  }
  std::sort(entries.begin(), entries.end());
  return entries;
}

std::string Base64(const std::string& bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size())
      chunk |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size())
      chunk |= static_cast<unsigned char>(bytes[i + 2]);
    out += kDigits[(chunk >> 18) & 63];
    out += kDigits[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[chunk & 63] : '=';
  }
  return out;
}

std::string Escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string ImageCell(const Image& image, const std::string& caption) {
  if (image.Width() == 0) {
    return "<td class=\"none\">" + Escaped(caption) + ": none</td>";
  }
  return "<td><img alt=\"" + Escaped(caption) + "\" src=\"data:image/png;base64," +
         Base64(EncodeImage(image, "image.png")) + "\"><br>" + Escaped(caption) + "</td>";
}

const char* VerdictName(ReportEntry::Verdict verdict) {
  switch (verdict) {
    case ReportEntry::Verdict::kPassed:
      return "passed";
    case ReportEntry::Verdict::kFailed:
      return "failed";
    case ReportEntry::Verdict::kMissing:
      return "missing";
    case ReportEntry::Verdict::kUnreadable:
      return "unreadable";
  }
  return "";
}

// The number of single-character insertions, deletions and substitutions that
// turn one name into the other.
std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string ClosestName(const std::string& name, const std::vector<std::string>& names) {
  std::string best;
  std::size_t best_distance = 4;
  for (const std::string& candidate : names) {
    const bool prefix = candidate.starts_with(name + "-") || name.starts_with(candidate + "-");
    const std::size_t distance = prefix ? 0 : EditDistance(name, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

namespace {

std::vector<std::string> Stems(const std::vector<fs::path>& paths) {
  std::vector<std::string> stems;
  for (const fs::path& path : paths) {
    stems.push_back(path.stem().string());
  }
  return stems;
}

std::string NotOurs(const std::string& what, const std::string& kind, const std::string& closest) {
  return what + ": not one of our " + kind + ", not compared" +
         (closest.empty() ? "" : " (did you mean " + closest + "?)");
}

bool IsImageName(const fs::path& path) {
  const std::string extension = path.extension().string();
  const bool image =
      extension == ".png" || extension == ".ppm" || extension == ".jpg" || extension == ".jpeg";
  return image && !path.stem().string().ends_with(".diff");
}

// file:///... for a file, each byte outside letters, digits and -._~/ percent-encoded.
std::string FileUrl(const fs::path& file) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string url = "file://";
  for (const unsigned char c : fs::absolute(file).generic_string()) {
    if (std::isalnum(c) || std::strchr("-._~/", c) != nullptr) {
      url += static_cast<char>(c);
    } else {
      url += {'%', kHex[c >> 4], kHex[c & 15]};
    }
  }
  return url;
}

// Where the chapter's figures and the sources' disagreements are explained: its web page,
// the README drawn (linked where scripts/site has made it), and the README's place in
// the repository (Markdown, which a browser shows as raw text: named, not linked).
std::string ReadmeNote(const std::string& chapter) {
  const fs::path site = fs::path(CGFS_SOURCE_DIR) / "out" / "site" / chapter / "index.html";
  std::error_code error;
  std::string note = "<p>The chapter's figures and where the sources disagree: ";
  if (fs::is_regular_file(site, error)) {
    note += "<a href=\"" + Escaped(FileUrl(site)) + "\">its web page</a>, or ";
  }
  return note + "its README, <code>chapters/" + Escaped(chapter) +
         "/README.md</code> in this repository" +
         (fs::is_regular_file(site, error) ? ""
                                           : " (<code>scripts/site</code> makes it a web page)") +
         ".</p>";
}

// For a failed figure of a chapter whose book functions have cases
// (tests/cases/CHAPTER.json): where they are, and the commands that run them against a
// Python or JavaScript chapter (docs/students.md). Empty otherwise.
std::string FunctionCasesNote(const ReportEntry& entry) {
  const fs::path cases = fs::path(CGFS_SOURCE_DIR) / "tests" / "cases" / (entry.chapter + ".json");
  std::error_code error;
  if (entry.verdict != ReportEntry::Verdict::kFailed || !fs::is_regular_file(cases, error)) {
    return "";
  }
  const std::string number = entry.chapter.substr(0, 2);
  return "<p class=\"cases\">Its functions one at a time, on the cases of <a href=\"" +
         Escaped(FileUrl(cases)) + "\">" + Escaped(entry.chapter) +
         ".json</a>: <code>node tools/check-functions/check-functions.js " + number +
         " YOUR_FILE</code> (a Python or JavaScript chapter; docs/students.md).</p>";
}

}  // namespace

std::vector<std::string> UnmatchedNames(const fs::path& folder, const fs::path& golden) {
  std::vector<std::string> chapters;
  for (const fs::path& chapter : SortedEntries(golden)) {
    chapters.push_back(chapter.filename().string());
  }
  std::vector<std::string> notes;
  std::error_code error;
  for (const fs::path& theirs : SortedEntries(folder)) {
    const std::string name = theirs.filename().string();
    if (!fs::is_directory(theirs, error)) {
      continue;
    }
    if (std::find(chapters.begin(), chapters.end(), name) == chapters.end()) {
      notes.push_back(NotOurs(name + "/", "chapter folders", ClosestName(name, chapters)));
      continue;
    }
    std::vector<fs::path> references;
    for (const fs::path& reference : SortedEntries(golden / name)) {
      if (reference.extension() == ".png") {
        references.push_back(reference);
      }
    }
    const std::vector<std::string> figures = Stems(references);
    for (const fs::path& file : SortedEntries(theirs)) {
      const std::string figure = file.stem().string();
      if (IsImageName(file) && std::find(figures.begin(), figures.end(), figure) == figures.end()) {
        notes.push_back(NotOurs(name + "/" + file.filename().string(), "figures",
                                ClosestName(figure, figures)));
      }
    }
  }
  return notes;
}

std::vector<ReportEntry> CompareFolder(const fs::path& folder, const fs::path& golden,
                                       bool list_missing) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw Error("cannot read the folder '" + folder.string() + "'" +
                (error ? ": " + error.message() : ": not a folder"));
  }
  std::vector<ReportEntry> entries;
  for (const fs::path& chapter : SortedEntries(golden)) {
    const fs::path theirs = folder / chapter.filename();
    if (!fs::is_directory(theirs, error)) {
      continue;
    }
    for (const fs::path& reference : SortedEntries(chapter)) {
      if (reference.extension() != ".png") {
        continue;
      }
      ReportEntry entry;
      entry.chapter = chapter.filename().string();
      entry.figure = reference.stem().string();
      for (const char* extension : {".png", ".ppm"}) {
        const fs::path candidate = theirs / (entry.figure + extension);
        if (fs::symlink_status(candidate, error).type() != fs::file_type::not_found && !error) {
          entry.actual_file = candidate;
          break;
        }
      }
      if (entry.actual_file.empty() && !list_missing) {
        continue;
      }
      entry.expected = ReadImage(reference);
      if (entry.actual_file.empty()) {
        entry.message = "no " + entry.figure + ".png or .ppm in " + theirs.string();
      } else {
        try {
          entry.actual = ReadImage(entry.actual_file);
          Comparison comparison = CompareImages(entry.expected, entry.actual);
          entry.verdict =
              comparison.passed ? ReportEntry::Verdict::kPassed : ReportEntry::Verdict::kFailed;
          // The diagnosis has a line of its own on the page: the numbers go without it.
          entry.diagnosis = std::move(comparison.diagnosis);
          comparison.diagnosis.clear();
          entry.message = Describe(comparison, entry.actual.Width(), entry.actual.Height());
          entry.difference = std::move(comparison.difference);
        } catch (const Error& bad) {  // not an image we can read
          entry.verdict = ReportEntry::Verdict::kUnreadable;
          entry.message = bad.what();
        } catch (const std::invalid_argument& bad) {  // another size than ours
          entry.verdict = ReportEntry::Verdict::kUnreadable;
          entry.message = bad.what();
        }
      }
      entries.push_back(std::move(entry));
    }
  }
  return entries;
}

void WriteReport(const std::vector<ReportEntry>& entries, const fs::path& html,
                 const std::string& title) {
  int counts[4] = {0, 0, 0, 0};
  for (const ReportEntry& entry : entries) {
    ++counts[static_cast<int>(entry.verdict)];
  }
  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>"
       << Escaped(title) << "</title>\n<style>\n"
       << "body{font-family:sans-serif;margin:1em}td{vertical-align:top;padding:4px;"
          "text-align:center}img{width:300px;image-rendering:pixelated;border:1px solid #ccc;"
          "cursor:zoom-in}img.full{width:auto;cursor:zoom-out}tr.missing img{width:100px}"
          "#check{display:none}"
          "tr.passed h3{color:#070}tr.failed h3,tr.unreadable h3{color:#b00}"
          "tr.missing h3{color:#a60}pre{text-align:left;white-space:pre-wrap;max-width:28em}"
          ".diagnosis{font-weight:bold}\n"
       << "</style></head><body>\n<h1>" << Escaped(title) << "</h1>\n"
       << "<p id=\"summary\"><span id=\"passed\">" << counts[0] << "</span> passed, "
       << "<span id=\"failed\">" << counts[1] + counts[3] << "</span> failed, "
       << "<span id=\"missing\">" << counts[2] << "</span> missing</p>\n"
       << "<p>Difference images: " << Escaped(DifferenceLegend())
       << ". Click an image to see it at full size.</p>\n<table>\n";
  for (const ReportEntry& entry : entries) {
    page << "<tr class=\"" << VerdictName(entry.verdict) << "\"><td><h3>" << Escaped(entry.chapter)
         << "/" << Escaped(entry.figure) << ": " << VerdictName(entry.verdict) << "</h3>";
    if (!entry.diagnosis.empty()) {
      page << "<p class=\"diagnosis\">" << Escaped(entry.diagnosis) << "</p>";
    }
    page << "<pre>" << Escaped(entry.message) << "</pre>" << ReadmeNote(entry.chapter)
         << FunctionCasesNote(entry) << "</td>" << ImageCell(entry.expected, "ours");
    if (entry.verdict != ReportEntry::Verdict::kMissing) {
      page << ImageCell(entry.actual, "yours") << ImageCell(entry.difference, "difference");
    }
    page << "</tr>\n";
  }
  // A hidden line the page fills in itself once loaded: how many of its images a
  // browser could show, and the verdicts counted from the rows (tests/report checks
  // both). A click on an image shows it at full size, another shrinks it back; opened
  // as report.html#click-test, the page clicks a failed figure's image twice itself and
  // adds the widths it had to the line.
  page << "</table>\n<p id=\"check\">(the browser has not counted the images yet)</p>\n"
       << "<script>\nfor (const image of document.images) {\n"
       << "  image.addEventListener('click', () => image.classList.toggle('full'));\n}\n"
       << "window.addEventListener('load', () => {\n"
       << "  const images = [...document.images];\n"
       << "  const shown = images.filter(i => i.complete && i.naturalWidth > 0).length;\n"
       << "  const rows = verdict => document.querySelectorAll('tr.' + verdict).length;\n"
       << "  document.getElementById('check').textContent = `images shown: ${shown} of "
          "${images.length}; rows passed: ${rows('passed')}, failed: "
          "${rows('failed') + rows('unreadable')}, missing: ${rows('missing')}`;\n"
       << "  const image = document.querySelector('tr.failed img');\n"
       << "  if (location.hash === '#click-test' && image) {\n"
       << "    const widths = [image.width];\n"
       << "    image.click();\n    widths.push(image.width);\n"
       << "    image.click();\n    widths.push(image.width);\n"
       << "    document.getElementById('check').textContent += `; click: ${widths.join(', ')} "
          "px`;\n  }\n"
       << "});\n</script>\n</body></html>\n";

  // Several test processes may write the page at once: each writes its own temporary
  // and renames it into place (WriteFileSafely).
  WriteFileSafely(html, page.str());
}

}  // namespace cgfs
