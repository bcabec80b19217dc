// Headless OpenGL through EGL's surfaceless platform (Mesa llvmpipe): no window, no display server.
// Every GL entry point is fetched with eglGetProcAddress, so only libEGL is linked and the same
// table serves the desktop-GL and the GLES context.
#pragma once

#include <GL/glcorearb.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "run/glsl_source.h"

namespace offsetgen::gl {

// The GL functions this project uses; X(pointer type, name without the "gl" prefix).
#define OFFSETGEN_GL_FUNCTIONS(X)                              \
  X(PFNGLGETERRORPROC, GetError)                               \
  X(PFNGLGETSTRINGPROC, GetString)                             \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                         \
  X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v)                     \
  X(PFNGLFINISHPROC, Finish)                                   \
  X(PFNGLCREATESHADERPROC, CreateShader)                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
  X(PFNGLDELETESHADERPROC, DeleteShader)                       \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                       \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                             \
  X(PFNGLUNIFORM1UIPROC, Uniform1ui)                           \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                             \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                             \
  X(PFNGLUNIFORM3FPROC, Uniform3f)                             \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                   \
  X(PFNGLBUFFERDATAPROC, BufferData)                           \
  X(PFNGLMAPBUFFERRANGEPROC, MapBufferRange)                   \
  X(PFNGLUNMAPBUFFERPROC, UnmapBuffer)                         \
  X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                 \
  X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                     \
  X(PFNGLGENTEXTURESPROC, GenTextures)                         \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                   \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                         \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                     \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                           \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                     \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                 \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)           \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                 \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)   \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)               \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)         \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)               \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)         \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
  X(PFNGLVIEWPORTPROC, Viewport)                               \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                           \
  X(PFNGLREADPIXELSPROC, ReadPixels)

struct Functions {
#define OFFSETGEN_GL_DECLARE(type, name) type name = nullptr;
  OFFSETGEN_GL_FUNCTIONS(OFFSETGEN_GL_DECLARE)
#undef OFFSETGEN_GL_DECLARE
};

enum class Api {
  Desktop43,  // OpenGL 4.3 core: compute shaders, "#version 430 core"
  Es30,       // OpenGL ES 3.0: "#version 300 es"
};

// Thrown when no headless GL is available; the message names the Debian packages to install.
struct Unavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown when a shader fails to compile or link; the message is the annotated driver log.
struct ShaderError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Makes a context of `api` current (created once per process and kept: creation costs far more
// than the work done in a typical call) and returns the function table.
// Before the first EGL call it sets EGL_PLATFORM=surfaceless and LIBGL_ALWAYS_SOFTWARE=1 unless
// the caller's environment already sets them, so results come from llvmpipe by default.
const Functions& make_current(Api api);

// GL_RENDERER / GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
std::string renderer();
std::string version();

// Throws std::runtime_error("<what>: GL error 0x...") when glGetError reports one.
void check_error(const Functions& gl, const char* what);

// One shader stage of a program; `source` carries the snippet position for error messages.
struct Stage {
  GLenum type;
  glsl::HostedSource source;
};

// Compiles and links; throws ShaderError with the log annotated with snippet/host lines.
GLuint build_program(const Functions& gl, const std::vector<Stage>& stages);

// "#version 430 core\n" or "#version 300 es\n".
std::string version_line(Api api);

}  // namespace offsetgen::gl
