// Values whose types only their own modules know: a scene's data of its body kind (SceneSpec::
// body_data), for example a body's size or its obstacles, and a task table's slots of a kind
// (TaskTable::kinds). General code copies and moves them and never looks inside; the module that
// owns a type reads and writes it through its header's accessors
// (framework/bodies/<kind>/include/).
#pragma once

#include <any>
#include <deque>

namespace jelly {

/// At most one value of each type, each made on first use with its type's default. References to
/// a part stay valid while the KindParts lives (parts are never moved once made). Copying copies
/// every part.
class KindParts {
 public:
  /// The part of type T, or nullptr when none was made.
  template <class T>
  const T* find() const {
    for (const std::any& a : parts_)
      if (const T* p = std::any_cast<T>(&a)) return p;
    return nullptr;
  }
  /// The part of type T, made with T's default when there is none.
  template <class T>
  T& get() {
    for (std::any& a : parts_)
      if (T* p = std::any_cast<T>(&a)) return *p;
    return *std::any_cast<T>(&parts_.emplace_back(T{}));
  }
  /// The part of type T, or a default T when none was made (read-only: makes nothing).
  template <class T>
  const T& get_or_default() const {
    static const T defaults{};
    const T* p = find<T>();
    return p ? *p : defaults;
  }

 private:
  std::deque<std::any> parts_;
};

}  // namespace jelly
