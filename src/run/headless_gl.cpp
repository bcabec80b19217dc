#include "run/headless_gl.h"

// Keep X11 headers (and their macros such as None/Bool) out: surfaceless needs no window system.
#define EGL_NO_X11
// libEGL is opened when the first context is made, not linked: the commands that never run a
// shader (generate, density, mesh, ...) then do not load the GL stack, about a millisecond of
// every process start.
#define EGL_EGL_PROTOTYPES 0
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace offsetgen::gl {
namespace {

// The EGL functions used here, fetched from libEGL.so.1 by load_egl().
#define OFFSETGEN_EGL_FUNCTIONS(X)               \
  X(PFNEGLGETERRORPROC, eglGetError)             \
  X(PFNEGLQUERYSTRINGPROC, eglQueryString)       \
  X(PFNEGLGETPROCADDRESSPROC, eglGetProcAddress) \
  X(PFNEGLINITIALIZEPROC, eglInitialize)         \
  X(PFNEGLTERMINATEPROC, eglTerminate)           \
  X(PFNEGLBINDAPIPROC, eglBindAPI)               \
  X(PFNEGLCHOOSECONFIGPROC, eglChooseConfig)     \
  X(PFNEGLCREATECONTEXTPROC, eglCreateContext)   \
  X(PFNEGLDESTROYCONTEXTPROC, eglDestroyContext) \
  X(PFNEGLMAKECURRENTPROC, eglMakeCurrent)

#define OFFSETGEN_EGL_DECLARE(type, name) type name = nullptr;
OFFSETGEN_EGL_FUNCTIONS(OFFSETGEN_EGL_DECLARE)
#undef OFFSETGEN_EGL_DECLARE

constexpr const char* kInstallHint =
    "install the Debian packages libegl1 libegl-mesa0 libgl1-mesa-dri (build: libegl-dev "
    "libopengl-dev libgles-dev), e.g. with tools/install_deps.sh";

std::string egl_error_text(const char* what) {
  char buf[64];
  std::snprintf(buf, sizeof buf, " (EGL error 0x%04x)", static_cast<unsigned>(eglGetError()));
  return std::string(what) + buf + ": " + kInstallHint;
}

// Opens libEGL and fills the pointers above, once per process. Throws Unavailable when libEGL or
// one of the functions is missing.
void load_egl() {
  static const std::string failure = [] {
    void* library = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);  // kept open until exit
    if (library == nullptr) return std::string("cannot open libEGL.so.1 (") + dlerror() + ")";
    std::string missing;
#define OFFSETGEN_EGL_LOAD(type, name)                  \
  name = reinterpret_cast<type>(dlsym(library, #name)); \
  if (name == nullptr) missing += " " #name;
    OFFSETGEN_EGL_FUNCTIONS(OFFSETGEN_EGL_LOAD)
#undef OFFSETGEN_EGL_LOAD
    return missing.empty() ? std::string() : "libEGL.so.1 lacks" + missing;
  }();
  if (!failure.empty()) throw Unavailable(failure + ": " + kInstallHint);
}

struct ContextSlot {
  EGLContext context = EGL_NO_CONTEXT;
  Functions functions;
};

struct Display {
  EGLDisplay display = EGL_NO_DISPLAY;
  ContextSlot desktop;
  ContextSlot es;

  static Display& instance() {
    static Display d;
    return d;
  }

  ~Display() {
    if (display == EGL_NO_DISPLAY) return;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (desktop.context != EGL_NO_CONTEXT) eglDestroyContext(display, desktop.context);
    if (es.context != EGL_NO_CONTEXT) eglDestroyContext(display, es.context);
    eglTerminate(display);
  }

  void open() {
    if (display != EGL_NO_DISPLAY) return;
    // Without a window system Mesa must be told which platform to use; software rendering keeps
    // results identical on machines with and without a GPU. Callers may override both.
    setenv("EGL_PLATFORM", "surfaceless", 0);
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
    load_egl();
    const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (client_ext == nullptr || std::string(client_ext).find("EGL_MESA_platform_surfaceless") == std::string::npos) {
      throw Unavailable("EGL has no EGL_MESA_platform_surfaceless: " + std::string(kInstallHint));
    }
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display == nullptr) {
      throw Unavailable("eglGetPlatformDisplayEXT missing: " + std::string(kInstallHint));
    }
    EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d == EGL_NO_DISPLAY) throw Unavailable(egl_error_text("no surfaceless EGL display"));
    EGLint major = 0, minor = 0;
    if (eglInitialize(d, &major, &minor) != EGL_TRUE) {
      throw Unavailable(egl_error_text("eglInitialize failed on the surfaceless display"));
    }
    display = d;
  }

  ContextSlot& slot(Api api) { return api == Api::Desktop43 ? desktop : es; }

  void create(Api api) {
    ContextSlot& s = slot(api);
    if (s.context != EGL_NO_CONTEXT) return;
    const bool is_es = api == Api::Es30;
    if (eglBindAPI(is_es ? EGL_OPENGL_ES_API : EGL_OPENGL_API) != EGL_TRUE) {
      throw Unavailable(egl_error_text(is_es ? "eglBindAPI(GLES) failed" : "eglBindAPI(GL) failed"));
    }
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, is_es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint n_configs = 0;
    eglChooseConfig(display, config_attribs, &config, 1, &n_configs);
    if (n_configs == 0) config = nullptr;  // == EGL_NO_CONFIG_KHR: fine for surfaceless use
    const EGLint es_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    const EGLint gl_attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext c = eglCreateContext(display, config, EGL_NO_CONTEXT, is_es ? es_attribs : gl_attribs);
    if (c == EGL_NO_CONTEXT) {
      throw Unavailable(egl_error_text(is_es ? "cannot create an OpenGL ES 3.0 context"
                                             : "cannot create an OpenGL 4.3 core context"));
    }
    s.context = c;
    make(api);
    // Loaded per context: EGL does not promise that a pointer fetched for one client API (GL or
    // GLES) is valid for the other.
    bool complete = true;
    std::string missing;
#define OFFSETGEN_GL_LOAD(type, name)                                       \
  s.functions.name = reinterpret_cast<type>(eglGetProcAddress("gl" #name)); \
  if (s.functions.name == nullptr) {                                        \
    complete = false;                                                       \
    missing += " gl" #name;                                                 \
  }
    OFFSETGEN_GL_FUNCTIONS(OFFSETGEN_GL_LOAD)
#undef OFFSETGEN_GL_LOAD
    if (!complete) throw Unavailable("GL entry points missing:" + missing + ": " + kInstallHint);
  }

  void make(Api api) {
    const bool is_es = api == Api::Es30;
    eglBindAPI(is_es ? EGL_OPENGL_ES_API : EGL_OPENGL_API);
    if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, slot(api).context) != EGL_TRUE) {
      throw Unavailable(egl_error_text("eglMakeCurrent (surfaceless) failed"));
    }
  }
};

Api g_current = Api::Desktop43;

std::string compile_log(const Functions& gl, GLuint shader) {
  GLint len = 0;
  gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
  std::string log(static_cast<std::size_t>(len > 0 ? len : 1), '\0');
  gl.GetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.c_str();
}

std::string link_log(const Functions& gl, GLuint program) {
  GLint len = 0;
  gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
  std::string log(static_cast<std::size_t>(len > 0 ? len : 1), '\0');
  gl.GetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.c_str();
}

const char* stage_name(GLenum type) {
  switch (type) {
    case GL_VERTEX_SHADER:
      return "vertex";
    case GL_FRAGMENT_SHADER:
      return "fragment";
    case GL_COMPUTE_SHADER:
      return "compute";
    default:
      return "shader";
  }
}

}  // namespace

const Functions& make_current(Api api) {
  Display& d = Display::instance();
  d.open();
  d.create(api);
  d.make(api);
  g_current = api;
  return d.slot(api).functions;
}

std::string renderer() {
  const auto* s = Display::instance().slot(g_current).functions.GetString(GL_RENDERER);
  return s ? reinterpret_cast<const char*>(s) : "";
}

std::string version() {
  const auto* s = Display::instance().slot(g_current).functions.GetString(GL_VERSION);
  return s ? reinterpret_cast<const char*>(s) : "";
}

void check_error(const Functions& gl, const char* what) {
  const GLenum e = gl.GetError();
  if (e == GL_NO_ERROR) return;
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04x", e);
  throw std::runtime_error(std::string(what) + ": GL error " + buf);
}

GLuint build_program(const Functions& gl, const std::vector<Stage>& stages) {
  const GLuint program = gl.CreateProgram();
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) gl.DeleteShader(s);
  };
  for (const Stage& st : stages) {
    const GLuint sh = gl.CreateShader(st.type);
    shaders.push_back(sh);
    const char* text = st.source.text.c_str();
    gl.ShaderSource(sh, 1, &text, nullptr);
    gl.CompileShader(sh);
    GLint ok = 0;
    gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
      const std::string msg = std::string(stage_name(st.type)) + " shader failed to compile:\n" +
                              glsl::annotate_log(compile_log(gl, sh), st.source);
      cleanup();
      gl.DeleteProgram(program);
      throw ShaderError(msg);
    }
    gl.AttachShader(program, sh);
  }
  gl.LinkProgram(program);
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  cleanup();
  if (ok != GL_TRUE) {
    const std::string log = link_log(gl, program);
    gl.DeleteProgram(program);
    throw ShaderError("program failed to link:\n" + log);
  }
  return program;
}

std::string version_line(Api api) { return api == Api::Desktop43 ? "#version 430 core\n" : "#version 300 es\n"; }

}  // namespace offsetgen::gl
