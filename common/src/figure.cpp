#include "cgfs/figure.h"

namespace cgfs {

Canvas RenderFigure(const Figure& figure, int width, int height) {
  Canvas canvas(width, height);
  figure.draw(canvas);
  return canvas;
}

}  // namespace cgfs
