#pragma once
// Images between the CPU and OpenGL: a framebuffer's pixels read back, and a linear image as a
// texture. CPU images run top row first, OpenGL's bottom row first; these turn the rows.
#include "core/image.h"
#include "gl/gl_object.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <string>
#include <vector>

namespace radview::gl {

// RGBA pixels of `colourBuffer` of a framebuffer (0: the window's), top row first.
std::vector<uint8_t> readBytePixels(GLuint framebuffer, GLenum colourBuffer, int width, int height);
std::vector<float> readFloatPixels(GLuint framebuffer, GLenum colourBuffer, int width, int height);

// A texture of a linear image (RGBA32F, nearest texel). Throws Error naming `source` for a size
// this OpenGL cannot hold.
GlObject linearTexture(const LinearImage& image, const std::string& source);

}  // namespace radview::gl
