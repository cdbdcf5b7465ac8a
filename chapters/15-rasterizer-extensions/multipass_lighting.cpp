#include "multipass_lighting.h"

AccumulationBuffer::AccumulationBuffer(const Canvas& canvas)
    : canvas_(&canvas),
      colors_(static_cast<std::size_t>(canvas.Width()) * static_cast<std::size_t>(canvas.Height()),
              Color(0, 0, 0)),
      last_pass_(colors_.size(), -1) {}

std::ptrdiff_t AccumulationBuffer::Index(int x, int y) const {
  const int column = canvas_->Width() / 2 + x;
  const int row = canvas_->Height() / 2 - y - 1;
  if (column < 0 || column >= canvas_->Width() || row < 0 || row >= canvas_->Height()) {
    return -1;
  }
  return static_cast<std::ptrdiff_t>(row) * canvas_->Width() + column;
}

void AccumulationBuffer::BeginPass() {
  ++pass_;
}

void AccumulationBuffer::Set(int x, int y, const Color& color) {
  const std::ptrdiff_t i = Index(x, y);
  if (i >= 0) {
    colors_[static_cast<std::size_t>(i)] = color;
    last_pass_[static_cast<std::size_t>(i)] = pass_;
  }
}

bool AccumulationBuffer::CanAdd(int x, int y) const {
  const std::ptrdiff_t i = Index(x, y);
  return i >= 0 && last_pass_[static_cast<std::size_t>(i)] != pass_;
}

bool AccumulationBuffer::Add(int x, int y, const Color& color) {
  if (!CanAdd(x, y)) {
    return false;
  }
  const auto i = static_cast<std::size_t>(Index(x, y));
  colors_[i] += color;
  last_pass_[i] = pass_;
  return true;
}

void AccumulationBuffer::WriteTo(Canvas& canvas) const {
  for (int y = -canvas.Height() / 2; y < canvas.Height() / 2; ++y) {
    for (int x = -canvas.Width() / 2; x < canvas.Width() / 2; ++x) {
      const auto i = static_cast<std::size_t>(Index(x, y));
      if (last_pass_[i] >= 0) {
        canvas.PutPixel(x, y, colors_[i]);
      }
    }
  }
}

bool PassDepthTest(const Pass& pass, DepthBuffer& depth_buffer, int x, int y, double depth) {
  if (!pass.sum || pass.first) {
    return depth_buffer.TestAndSet(x, y, depth);
  }
  return depth_buffer.Holds(x, y, depth) && (!pass.stencil || pass.stencil->At(x, y) == 0) &&
         pass.sum->CanAdd(x, y);
}

void PassWrite(const Pass& pass, Canvas& canvas, int x, int y, const Color& color) {
  if (!pass.sum) {
    canvas.PutPixel(x, y, color);
  } else if (pass.first) {
    pass.sum->Set(x, y, color);
  } else {
    pass.sum->Add(x, y, color);
  }
}
