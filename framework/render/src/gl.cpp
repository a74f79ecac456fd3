#include "jelly/render/gl.hpp"

namespace jelly::render {

std::string Gl::load(void* (*get_proc)(const char*)) {
  std::string missing;
#define JELLY_GL_LOAD(name, type)                      \
  name = reinterpret_cast<type>(get_proc("gl" #name)); \
  if (!name) missing += (missing.empty() ? "gl" : ", gl") + std::string(#name);
  JELLY_GL_FUNCTIONS(JELLY_GL_LOAD)
#undef JELLY_GL_LOAD
  return missing;
}

std::string Gl::describe() const {
  if (!GetString) return "no GL";
  auto text = [&](GLenum e) {
    const GLubyte* s = GetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_VERSION) + " / " + text(GL_RENDERER);
}

}  // namespace jelly::render
