// A chapter's command-line options, read in its web page: the page gives the words a
// command line would (--model spider.obj), and the chapter's own AddChapterOptions
// (options.h) reads them as its program does.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace cgfs {

// Parses `words` (a command line without the program's name) into the options that
// `declare` puts on a new CLI::App, then runs what they call once read. Errors are
// reported as the programs report them (cgfs::RunReportingErrors: one line on the
// standard error, which the page shows, as it shows warnings): 0 when all went well,
// 2 when not.
int ReadOptions(const char* program, const std::function<void(CLI::App&)>& declare,
                const std::vector<std::string>& words);

}  // namespace cgfs
