#include "multipass_lighting.h"

AccumulationBuffer::AccumulationBuffer(const Canvas& canvas) : sums_(canvas, Sum{}) {}

void AccumulationBuffer::BeginPass() {
  ++pass_;
}

void AccumulationBuffer::Set(int x, int y, const Color& color) {
  if (Sum* sum = sums_.Find(x, y)) {
    *sum = {color, pass_};
  }
}

bool AccumulationBuffer::CanAdd(int x, int y) const {
  const Sum* sum = sums_.Find(x, y);
  return sum && sum->last_pass != pass_;
}

bool AccumulationBuffer::Add(int x, int y, const Color& color) {
  Sum* sum = sums_.Find(x, y);
  if (!sum || sum->last_pass == pass_) {
    return false;
  }
  sum->color += color;
  sum->last_pass = pass_;
  return true;
}

void AccumulationBuffer::WriteTo(Canvas& canvas) const {
  for (int y = -canvas.Height() / 2; y < canvas.Height() / 2; ++y) {
    for (int x = -canvas.Width() / 2; x < canvas.Width() / 2; ++x) {
      const Sum* sum = sums_.Find(x, y);
      if (sum && sum->last_pass >= 0) {
        canvas.PutPixel(x, y, sum->color);
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
