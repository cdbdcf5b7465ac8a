#include "program/window.h"

#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "program/camera_controls.h"
#include "program/error.h"
#include "program/image_files.h"

namespace cgfs {

namespace {

// SDL's window, renderer and texture, released in the reverse order.
struct Sdl {
  Sdl() {
    // Without a display SDL falls back to drawing off screen, where nobody would see
    // the window: that is no display too, unless SDL_VIDEODRIVER asks for it.
    // Only the displays the environment names are tried (a Wayland library probed
    // without one prints a complaint of its own).
    const bool asked = std::getenv("SDL_VIDEODRIVER") != nullptr;
    std::string displays;
    if (std::getenv("DISPLAY") != nullptr) {
      displays = "x11";
    }
    if (std::getenv("WAYLAND_DISPLAY") != nullptr) {
      displays += displays.empty() ? "wayland" : ",wayland";
    }
    if (!asked) {
      SDL_SetHint(SDL_HINT_VIDEODRIVER, displays.c_str());
    }
    const std::string driver = (asked || !displays.empty()) && SDL_Init(SDL_INIT_VIDEO) == 0
                                   ? SDL_GetCurrentVideoDriver()
                                   : "";
    if (driver.empty() || (!asked && (driver == "offscreen" || driver == "dummy"))) {
      const char* display = std::getenv("DISPLAY");
      const std::string why = displays.empty() && !asked ? "" : std::string(": ") + SDL_GetError();
      SDL_Quit();
      throw Error(std::string("--window: no display to open a window on (DISPLAY is ") +
                  (display != nullptr ? display : "not set") + why + ")");
    }
  }
  ~Sdl() {
    for (SDL_Texture* each : {preview, texture}) {
      if (each != nullptr) {
        SDL_DestroyTexture(each);
      }
    }
    if (renderer != nullptr) {
      SDL_DestroyRenderer(renderer);
    }
    if (window != nullptr) {
      SDL_DestroyWindow(window);
    }
    SDL_Quit();
  }
  Sdl(const Sdl&) = delete;
  Sdl& operator=(const Sdl&) = delete;

  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;
  SDL_Texture* preview = nullptr;  // half the size, stretched over the window
};

void Check(bool ok, const char* what) {
  if (!ok) {
    throw Error(std::string("--window: ") + what + ": " + SDL_GetError());
  }
}

// The figure shown, drawn by the chapter's code, and how long that took.
struct Shown {
  Canvas canvas{2, 2};
  double milliseconds = 0;
  bool preview = false;  // drawn at half size while the camera moves
};

Shown Draw(const Figure& figure, int width, int height, const View& view) {
  const auto start = std::chrono::steady_clock::now();
  Shown shown{RenderFigure(figure, width, height, figure.draw_from ? view : View{}), 0};
  shown.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return shown;
}

// What a key does to the camera; nothing for keys that do not move it.
std::optional<CameraKey> CameraKeyOf(SDL_Keycode key) {
  static constexpr std::pair<SDL_Keycode, CameraKey> kKeys[] = {
      {SDLK_UP, CameraKey::kForward},  {SDLK_DOWN, CameraKey::kBack},
      {SDLK_d, CameraKey::kRight},     {SDLK_a, CameraKey::kLeft},
      {SDLK_PAGEUP, CameraKey::kUp},   {SDLK_PAGEDOWN, CameraKey::kDown},
      {SDLK_q, CameraKey::kTurnLeft},  {SDLK_e, CameraKey::kTurnRight},
      {SDLK_HOME, CameraKey::kLookUp}, {SDLK_END, CameraKey::kLookDown},
  };
  for (const auto& [code, camera_key] : kKeys) {
    if (code == key) {
      return camera_key;
    }
  }
  return std::nullopt;
}

void Present(Sdl& sdl, const std::string& chapter, const Figure& figure, const Shown& shown,
             const View& view) {
  const Image& image = shown.canvas.GetImage();
  SDL_Texture* texture = shown.preview ? sdl.preview : sdl.texture;
  Check(SDL_UpdateTexture(texture, nullptr, image.Bytes().data(), image.Width() * 3) == 0,
        "cannot update the picture");
  SDL_RenderClear(sdl.renderer);
  SDL_RenderCopy(sdl.renderer, texture, nullptr, nullptr);
  SDL_RenderPresent(sdl.renderer);
  char time[32];
  std::snprintf(time, sizeof time, "%.1f ms", shown.milliseconds);
  std::string title = chapter + ": " + figure.name + " - " + CaptionOfDrawn(figure) + " - " + time;
  if (figure.draw_from && !(view == View{})) {
    title += " - view " + FormatView(view);
  }
  if (shown.preview) {
    title += " - half resolution while moving";
  }
  SDL_SetWindowTitle(sdl.window, title.c_str());
}

void Open(Sdl& sdl, const std::string& chapter, int width, int height, int preview_width,
          int preview_height) {
  sdl.window = SDL_CreateWindow(chapter.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                                width, height, SDL_WINDOW_SHOWN);
  Check(sdl.window != nullptr, "cannot open a window");
  sdl.renderer = SDL_CreateRenderer(sdl.window, -1, 0);
  Check(sdl.renderer != nullptr, "cannot draw in the window");
  sdl.texture = SDL_CreateTexture(sdl.renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING,
                                  width, height);
  sdl.preview = SDL_CreateTexture(sdl.renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING,
                                  preview_width, preview_height);
  Check(sdl.texture != nullptr && sdl.preview != nullptr, "cannot make the picture");
}

// S: the figure shown into `output`, through the safe write path, and where it went; or,
// when it cannot be written, why, in one line, with the view all the same (the window
// stays open: where the camera was walked to is not lost).
void Save(const Figure& figure, const Shown& shown, const std::filesystem::path& output,
          const std::string& format, const View& view) {
  const std::filesystem::path file = output / (figure.name + "." + format);
  try {
    std::filesystem::create_directories(output);
    WriteImage(shown.canvas.GetImage(), file);
    std::cout << "saved " << file.string();
  } catch (const std::exception& error) {
    std::cerr << "window: not saved: " << OneLine(error.what()) << std::endl;
    std::cout << "not saved";
  }
  if (figure.draw_from) {
    std::cout << " (--view " << FormatView(view) << ")";
  }
  std::cout << std::endl;
}

// How far the mouse was dragged (left button held): this motion and every one already
// queued behind it, so that one frame follows however many motions came while the last
// frame was drawn.
std::pair<int, int> DragSoFar(const SDL_MouseMotionEvent& first) {
  int right = first.xrel;
  int down = first.yrel;
  SDL_PumpEvents();
  SDL_Event next;
  while (SDL_PeepEvents(&next, 1, SDL_GETEVENT, SDL_MOUSEMOTION, SDL_MOUSEMOTION) == 1) {
    if ((next.motion.state & SDL_BUTTON_LMASK) != 0) {
      right += next.motion.xrel;
      down += next.motion.yrel;
    }
  }
  return {right, down};
}

// The window's state: the figure shown, from which view, drawn how.
class Session {
 public:
  Session(const std::string& chapter, const std::vector<const Figure*>& figures, int width,
          int height, const View& view)
      : chapter_(chapter),
        figures_(figures),
        width_(width),
        height_(height),
        // While the camera moves, frames are drawn at half the size and stretched; the
        // full one follows after kSettleMilliseconds without a key.
        preview_width_(PreviewSide(width)),
        preview_height_(PreviewSide(height)),
        start_view_(view),
        view_(view) {
    Open(sdl_, chapter, width, height, preview_width_, preview_height_);
  }

  void Show(std::size_t index, bool preview = false) {
    index_ = index;
    const Figure& figure = *figures_[index];
    shown_ = preview ? Draw(figure, preview_width_, preview_height_, view_)
                     : Draw(figure, width_, height_, view_);
    shown_.preview = preview;
    Present();
  }
  void Present() { cgfs::Present(sdl_, chapter_, *figures_[index_], shown_, view_); }
  bool Preview() const { return shown_.preview; }
  std::size_t Index() const { return index_; }

  // Dragging the mouse: the camera turns with it, `right` and `down` pixels.
  void Drag(int right, int down) {
    if (figures_[index_]->draw_from && (right != 0 || down != 0)) {
      view_ = Dragged(view_, right, down);
      Show(index_, true);
    }
  }

  // What a key does; false when it closes the window.
  bool Press(SDL_Keycode key, const std::filesystem::path& output, const std::string& format) {
    const std::size_t count = figures_.size();
    if (const std::optional<CameraKey> camera_key = CameraKeyOf(key)) {
      if (figures_[index_]->draw_from) {
        view_ = Moved(view_, *camera_key);
        Show(index_, true);
      }
      return true;
    }
    switch (key) {
      case SDLK_ESCAPE:
        return false;
      case SDLK_RIGHT:
        Show((index_ + 1) % count);
        break;
      case SDLK_LEFT:
        Show((index_ + count - 1) % count);
        break;
      case SDLK_c:
        if (const int partner = CostPartner(figures_, index_); partner >= 0) {
          Show(static_cast<std::size_t>(partner));
        }
        break;
      case SDLK_r:
        view_ = start_view_;
        Show(index_);
        break;
      case SDLK_s:
        if (shown_.preview) {
          Show(index_);  // what is saved is always the full picture
        }
        Save(*figures_[index_], shown_, output, format, view_);
        break;
      case SDLK_h:
      case SDLK_F1:
        std::cout << kWindowKeys << std::endl;
        break;
      default:
        break;
    }
    return true;
  }

 private:
  Sdl sdl_;
  std::string chapter_;
  const std::vector<const Figure*>& figures_;
  int width_, height_, preview_width_, preview_height_;
  View start_view_, view_;
  std::size_t index_ = 0;
  Shown shown_;
};

}  // namespace

void ShowFigures(const std::string& chapter, const std::vector<const Figure*>& figures, int width,
                 int height, const std::filesystem::path& output, const std::string& format,
                 const View& view) {
  if (figures.empty()) {
    return;
  }
  Session session(chapter, figures, width, height, view);
  std::cout << kWindowKeys << std::endl;
  session.Show(0);
  SDL_Event event;
  while (true) {
    if (session.Preview() && SDL_WaitEventTimeout(&event, kSettleMilliseconds) == 0) {
      session.Show(session.Index());  // the camera has stopped: the full picture
      continue;
    }
    if (!session.Preview() && SDL_WaitEvent(&event) == 0) {
      return;
    }
    if (event.type == SDL_QUIT) {
      return;
    }
    if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_EXPOSED) {
      session.Present();
    }
    if (event.type == SDL_KEYDOWN && !session.Press(event.key.keysym.sym, output, format)) {
      return;
    }
    if (event.type == SDL_MOUSEMOTION && (event.motion.state & SDL_BUTTON_LMASK) != 0) {
      const auto [right, down] = DragSoFar(event.motion);
      session.Drag(right, down);
    }
  }
}

}  // namespace cgfs
