// A value for every pixel of the canvas, such as a depth ("Depth Buffering"). A cell
// is found from canvas coordinates (x, y) exactly as PutPixel finds a pixel of the
// image (chapter 1's mapping, Canvas::ToScreen), so a buffer and the canvas never
// disagree about which pixel (x, y) is.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "cgfs/canvas.h"

template <typename T>
class CanvasGrid {
 public:
  CanvasGrid(const cgfs::Canvas& canvas, const T& initial)
      : canvas_(&canvas),
        cells_(static_cast<std::size_t>(canvas.Width()) * static_cast<std::size_t>(canvas.Height()),
               initial) {}

  // The cell of pixel (x, y), or nullptr for a pixel off the canvas.
  T* Find(int x, int y) {
    const std::optional<std::size_t> i = Index(x, y);
    return i ? &cells_[*i] : nullptr;
  }
  const T* Find(int x, int y) const {
    const std::optional<std::size_t> i = Index(x, y);
    return i ? &cells_[*i] : nullptr;
  }

  // Every cell set to `value`.
  void Fill(const T& value) { cells_.assign(cells_.size(), value); }

 private:
  std::optional<std::size_t> Index(int x, int y) const {
    const std::optional<cgfs::ScreenPoint> screen = canvas_->ToScreen(x, y);
    if (!screen) {
      return std::nullopt;
    }
    return static_cast<std::size_t>(screen->row) * static_cast<std::size_t>(canvas_->Width()) +
           static_cast<std::size_t>(screen->column);
  }

  const cgfs::Canvas* canvas_;
  std::vector<T> cells_;
};
