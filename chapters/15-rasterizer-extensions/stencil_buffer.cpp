#include "stencil_buffer.h"

#include <algorithm>

StencilBuffer::StencilBuffer(const Canvas& canvas)
    : canvas_(&canvas),
      counts_(static_cast<std::size_t>(canvas.Width()) * static_cast<std::size_t>(canvas.Height()),
              0) {}

int StencilBuffer::At(int x, int y) const {
  const std::optional<cgfs::ScreenPoint> screen = canvas_->ToScreen(x, y);
  if (!screen) {
    return 0;
  }
  return counts_[static_cast<std::size_t>(screen->row) *
                     static_cast<std::size_t>(canvas_->Width()) +
                 static_cast<std::size_t>(screen->column)];
}

void StencilBuffer::Add(int x, int y, int delta) {
  const std::optional<cgfs::ScreenPoint> screen = canvas_->ToScreen(x, y);
  if (screen) {
    counts_[static_cast<std::size_t>(screen->row) * static_cast<std::size_t>(canvas_->Width()) +
            static_cast<std::size_t>(screen->column)] += delta;
  }
}

void StencilBuffer::Clear() {
  std::fill(counts_.begin(), counts_.end(), 0);
}
