// How far the drawing of a figure has got, for a program that shows it (the chapter
// program shows a long render's progress on a terminal). A renderer that draws in parts
// reports the fraction done after each part, from any thread.
#pragma once

namespace cgfs {

void ReportProgress(double fraction);

// The fraction last reported since ResetProgress, or -1 when none has been.
double ReportedProgress();
void ResetProgress();

}  // namespace cgfs
