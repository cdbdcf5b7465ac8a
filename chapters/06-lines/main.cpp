// Chapter 6, "Lines": renders the chapter's figures into out/06-lines/.
#include <string>
#include <vector>

#include "cgfs/chapter_main.h"
#include "rasterizer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program("06-lines",
                               "Chapter 6, Lines: DrawLine for any slope, and Interpolate.");
  std::vector<std::string> draft_names;
  program.Options().AddStrings(
      "--draw-line", "VERSION",
      "also draw all-directions-VERSION with one of the chapter's earlier DrawLine versions: "
      "slope-intercept, incremental, left-to-right, x-of-y, both-cases, or all (repeatable)",
      &draft_names);
  return program.Run(argc, argv, [&] {
    std::vector<DrawLineDraft> drafts;
    for (const std::string& name : draft_names) {
      DrawLineDraft draft;
      if (name == "all") {
        const std::vector<DrawLineDraft> all = AllDrafts();
        drafts.insert(drafts.end(), all.begin(), all.end());
      } else if (DraftFromName(name, &draft)) {
        drafts.push_back(draft);
      } else {
        throw cgfs::UsageError("--draw-line: no version named '" + name + "'");
      }
    }
    return Figures(drafts);
  });
}
