#include "jelly/render/body_view.hpp"

#include "jelly/session/assignments.hpp"

namespace jelly::render {

const BodyView* view_of(const SceneSpec& scene) {
  const std::string_view kind = session::body_name(scene.body_kind);
  for (const BodyView* view : body_views())
    if (view->kind() == kind) return view;
  return nullptr;
}

std::vector<const BodyView*> views_in(const World& world) {
  std::vector<const BodyView*> out;
  for (const BodyView* view : body_views())
    if (view->present(world)) out.push_back(view);
  return out;
}

}  // namespace jelly::render
