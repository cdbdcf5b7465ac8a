#include "image_decoders.h"

#include <png.h>
// jpeglib.h needs FILE and size_t declared before it.
#include <jpeglib.h>
#include <cstddef>
#include <cstdio>

#include <csetjmp>
#include <cstring>
#include <vector>

#include "program/error.h"

namespace cgfs::detail {

namespace fs = std::filesystem;

namespace {

// Both libraries report errors by calling back, and we leave their code with longjmp.
// The functions that call them set the jump point and hold nothing that needs a
// destructor, so the jump skips none; they return false, and the message is kept here.
struct DecoderMessage {
  char text[JMSG_LENGTH_MAX > 200 ? JMSG_LENGTH_MAX : 200] = {};
};

// --- PNG -------------------------------------------------------------------------

struct PngSource {
  const unsigned char* bytes = nullptr;
  std::size_t size = 0;
  std::size_t position = 0;
  DecoderMessage message;
};

void PngRead(png_structp png, png_bytep out, png_size_t count) {
  auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
  if (count > source->size - source->position) {
    png_error(png, "the file ends too early");
  }
  std::memcpy(out, source->bytes + source->position, count);
  source->position += count;
}

[[noreturn]] void PngError(png_structp png, png_const_charp text) {
  auto* source = static_cast<PngSource*>(png_get_error_ptr(png));
  std::snprintf(source->message.text, sizeof source->message.text, "%s", text);
  png_longjmp(png, 1);
}

void PngWarning(png_structp, png_const_charp) {}

// The header, and the transforms that make every PNG 8-bit RGB.
bool PngReadHeader(png_structp png, png_infop info) {
  if (setjmp(png_jmpbuf(png))) {
    return false;
  }
  png_set_user_limits(png, static_cast<png_uint_32>(kMaxSide), static_cast<png_uint_32>(kMaxSide));
  png_read_info(png, info);
  png_set_strip_16(png);
  png_set_packing(png);
  png_set_palette_to_rgb(png);
  png_set_expand_gray_1_2_4_to_8(png);
  png_set_gray_to_rgb(png);
  png_set_strip_alpha(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return true;
}

bool PngReadRows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) {
    return false;
  }
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

// --- JPEG ------------------------------------------------------------------------

// A progressive JPEG can hold thousands of tiny scans that take minutes to decode;
// real ones have about ten.
constexpr int kMaxJpegScans = 500;

struct JpegErrors {
  jpeg_error_mgr manager;  // first: libjpeg sees a pointer to it
  std::jmp_buf jump;
  DecoderMessage message;
};

[[noreturn]] void JpegError(j_common_ptr cinfo) {
  auto* errors = reinterpret_cast<JpegErrors*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, errors->message.text);
  std::longjmp(errors->jump, 1);
}

// A warning is corrupt data (a JPEG that ends early, a bad Huffman code): refused.
void JpegMessage(j_common_ptr cinfo, int level) {
  if (level < 0) {
    JpegError(cinfo);
  }
}

void JpegProgress(j_common_ptr cinfo) {
  auto* decompress = reinterpret_cast<j_decompress_ptr>(cinfo);
  if (decompress->input_scan_number > kMaxJpegScans) {
    auto* errors = reinterpret_cast<JpegErrors*>(cinfo->err);
    std::snprintf(errors->message.text, sizeof errors->message.text, "more than %d scans",
                  kMaxJpegScans);
    std::longjmp(errors->jump, 1);
  }
}

bool JpegReadHeader(j_decompress_ptr cinfo, JpegErrors& errors, const std::string& bytes) {
  if (setjmp(errors.jump)) {
    return false;
  }
  jpeg_mem_src(cinfo, reinterpret_cast<const unsigned char*>(bytes.data()),
               static_cast<unsigned long>(bytes.size()));
  jpeg_read_header(cinfo, TRUE);
  cinfo->out_color_space = JCS_RGB;
  return true;
}

bool JpegReadRows(j_decompress_ptr cinfo, JpegErrors& errors, unsigned char* pixels) {
  if (setjmp(errors.jump)) {
    return false;
  }
  jpeg_start_decompress(cinfo);
  if (cinfo->output_components != 3) {
    std::snprintf(errors.message.text, sizeof errors.message.text,
                  "it decodes to %d channels, not RGB", cinfo->output_components);
    return false;
  }
  const std::size_t stride = static_cast<std::size_t>(cinfo->output_width) * 3;
  while (cinfo->output_scanline < cinfo->output_height) {
    JSAMPROW row = pixels + stride * cinfo->output_scanline;
    jpeg_read_scanlines(cinfo, &row, 1);
  }
  jpeg_finish_decompress(cinfo);
  return true;
}

}  // namespace

Image DecodePng(const std::string& bytes, const fs::path& path) {
  PngSource source{reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), 0, {}};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &source, PngError, PngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  struct Release {
    png_structp* png;
    png_infop* info;
    ~Release() { png_destroy_read_struct(png, info, nullptr); }
  } release{&png, &info};
  if (!png || !info) {
    throw Error("cannot read " + Quoted(path) + ": out of memory");
  }
  png_set_read_fn(png, &source, PngRead);
  const auto fail = [&] {
    return Error(Quoted(path) + " is not a readable PNG image (" + source.message.text + ")");
  };
  if (!PngReadHeader(png, info)) {
    throw fail();
  }
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  CheckDeclaredSize(width, height, path, "PNG");
  if (png_get_rowbytes(png, info) != static_cast<png_size_t>(width) * 3) {
    throw Error(Quoted(path) + " is not a readable PNG image (not 8-bit RGB once converted)");
  }
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 3);
  std::vector<png_bytep> rows(height);
  for (png_uint_32 y = 0; y < height; ++y) {
    rows[y] = pixels.data() + static_cast<std::size_t>(y) * width * 3;
  }
  if (!PngReadRows(png, rows.data())) {
    throw fail();
  }
  return Image(static_cast<int>(width), static_cast<int>(height), std::move(pixels));
}

Image DecodeJpeg(const std::string& bytes, const fs::path& path) {
  jpeg_decompress_struct cinfo{};
  JpegErrors errors{};
  cinfo.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = JpegError;
  errors.manager.emit_message = JpegMessage;
  jpeg_create_decompress(&cinfo);
  struct Release {
    jpeg_decompress_struct* cinfo;
    ~Release() { jpeg_destroy_decompress(cinfo); }
  } release{&cinfo};
  jpeg_progress_mgr progress{};
  progress.progress_monitor = JpegProgress;
  cinfo.progress = &progress;
  const auto fail = [&] {
    return Error(Quoted(path) + " is not a readable JPEG image (" + errors.message.text + ")");
  };
  if (!JpegReadHeader(&cinfo, errors, bytes)) {
    throw fail();
  }
  CheckDeclaredSize(cinfo.image_width, cinfo.image_height, path, "JPEG");
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(cinfo.image_width) *
                                   cinfo.image_height * 3);
  if (!JpegReadRows(&cinfo, errors, pixels.data())) {
    throw fail();
  }
  return Image(static_cast<int>(cinfo.image_width), static_cast<int>(cinfo.image_height),
               std::move(pixels));
}

}  // namespace cgfs::detail
