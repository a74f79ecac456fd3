// OpenGL 3.3 core functions, loaded at run time into a table of function pointers.
//
// The render library links neither libGL nor libOSMesa: the window backend fills this table from
// glfwGetProcAddress, the off-screen backend from OSMesaGetProcAddress (libOSMesa is dlopen'ed),
// so one process never has both GL libraries linked (their symbols clash). Everything that draws
// receives a `const Gl&` and calls `gl.Clear(...)` instead of `glClear(...)`.
#pragma once

#include <GL/glcorearb.h>  // types and constants only (no prototypes without GL_GLEXT_PROTOTYPES)

#include <string>

namespace jelly::render {

// X-macro list: (name without the "gl" prefix, PFN type).
#define JELLY_GL_FUNCTIONS(X)                                                \
  X(ActiveTexture, PFNGLACTIVETEXTUREPROC)                                   \
  X(AttachShader, PFNGLATTACHSHADERPROC)                                     \
  X(BindBuffer, PFNGLBINDBUFFERPROC)                                         \
  X(BindFramebuffer, PFNGLBINDFRAMEBUFFERPROC)                               \
  X(BindRenderbuffer, PFNGLBINDRENDERBUFFERPROC)                             \
  X(BindVertexArray, PFNGLBINDVERTEXARRAYPROC)                               \
  X(BlendFunc, PFNGLBLENDFUNCPROC)                                           \
  X(BlitFramebuffer, PFNGLBLITFRAMEBUFFERPROC)                               \
  X(BufferData, PFNGLBUFFERDATAPROC)                                         \
  X(BufferSubData, PFNGLBUFFERSUBDATAPROC)                                   \
  X(CheckFramebufferStatus, PFNGLCHECKFRAMEBUFFERSTATUSPROC)                 \
  X(Clear, PFNGLCLEARPROC)                                                   \
  X(ClearColor, PFNGLCLEARCOLORPROC)                                         \
  X(CompileShader, PFNGLCOMPILESHADERPROC)                                   \
  X(CreateProgram, PFNGLCREATEPROGRAMPROC)                                   \
  X(CreateShader, PFNGLCREATESHADERPROC)                                     \
  X(DeleteBuffers, PFNGLDELETEBUFFERSPROC)                                   \
  X(DeleteFramebuffers, PFNGLDELETEFRAMEBUFFERSPROC)                         \
  X(DeleteProgram, PFNGLDELETEPROGRAMPROC)                                   \
  X(DeleteRenderbuffers, PFNGLDELETERENDERBUFFERSPROC)                       \
  X(DeleteShader, PFNGLDELETESHADERPROC)                                     \
  X(DeleteVertexArrays, PFNGLDELETEVERTEXARRAYSPROC)                         \
  X(DepthFunc, PFNGLDEPTHFUNCPROC)                                           \
  X(DepthMask, PFNGLDEPTHMASKPROC)                                           \
  X(Disable, PFNGLDISABLEPROC)                                               \
  X(DrawArrays, PFNGLDRAWARRAYSPROC)                                         \
  X(DrawBuffer, PFNGLDRAWBUFFERPROC)                                         \
  X(DrawElements, PFNGLDRAWELEMENTSPROC)                                     \
  X(Enable, PFNGLENABLEPROC)                                                 \
  X(EnableVertexAttribArray, PFNGLENABLEVERTEXATTRIBARRAYPROC)               \
  X(Finish, PFNGLFINISHPROC)                                                 \
  X(FramebufferRenderbuffer, PFNGLFRAMEBUFFERRENDERBUFFERPROC)               \
  X(GenBuffers, PFNGLGENBUFFERSPROC)                                         \
  X(GenFramebuffers, PFNGLGENFRAMEBUFFERSPROC)                               \
  X(GenRenderbuffers, PFNGLGENRENDERBUFFERSPROC)                             \
  X(GenVertexArrays, PFNGLGENVERTEXARRAYSPROC)                               \
  X(GetError, PFNGLGETERRORPROC)                                             \
  X(GetIntegerv, PFNGLGETINTEGERVPROC)                                       \
  X(GetProgramInfoLog, PFNGLGETPROGRAMINFOLOGPROC)                           \
  X(GetProgramiv, PFNGLGETPROGRAMIVPROC)                                     \
  X(GetShaderInfoLog, PFNGLGETSHADERINFOLOGPROC)                             \
  X(GetShaderiv, PFNGLGETSHADERIVPROC)                                       \
  X(GetString, PFNGLGETSTRINGPROC)                                           \
  X(GetUniformLocation, PFNGLGETUNIFORMLOCATIONPROC)                         \
  X(LineWidth, PFNGLLINEWIDTHPROC)                                           \
  X(LinkProgram, PFNGLLINKPROGRAMPROC)                                       \
  X(PixelStorei, PFNGLPIXELSTOREIPROC)                                       \
  X(PolygonOffset, PFNGLPOLYGONOFFSETPROC)                                   \
  X(ReadBuffer, PFNGLREADBUFFERPROC)                                         \
  X(ReadPixels, PFNGLREADPIXELSPROC)                                         \
  X(RenderbufferStorageMultisample, PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC) \
  X(Scissor, PFNGLSCISSORPROC)                                               \
  X(ShaderSource, PFNGLSHADERSOURCEPROC)                                     \
  X(Uniform1f, PFNGLUNIFORM1FPROC)                                           \
  X(Uniform1i, PFNGLUNIFORM1IPROC)                                           \
  X(Uniform2f, PFNGLUNIFORM2FPROC)                                           \
  X(Uniform3f, PFNGLUNIFORM3FPROC)                                           \
  X(Uniform4f, PFNGLUNIFORM4FPROC)                                           \
  X(UniformMatrix4fv, PFNGLUNIFORMMATRIX4FVPROC)                             \
  X(UseProgram, PFNGLUSEPROGRAMPROC)                                         \
  X(VertexAttribPointer, PFNGLVERTEXATTRIBPOINTERPROC)                       \
  X(Viewport, PFNGLVIEWPORTPROC)

/// The GL 3.3 core functions the renderer uses. Fill with load(); all members are non-null after
/// a successful load.
struct Gl {
#define JELLY_GL_MEMBER(name, type) type name = nullptr;
  JELLY_GL_FUNCTIONS(JELLY_GL_MEMBER)
#undef JELLY_GL_MEMBER

  /// Resolves every function through `get_proc` (the current context must be a 3.3 core one).
  /// Returns "" on success, else the names of the functions that could not be found.
  std::string load(void* (*get_proc)(const char* name));
  /// "4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string describe() const;
};

}  // namespace jelly::render
