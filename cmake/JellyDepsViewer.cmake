# The viewer's libraries (included by JellyDeps.cmake when JELLY_BUILD_VIEWER is on), same rules:
#   glfw              GLFW 3.3 (its own CMake when bundled: X11 on Linux, win32 on Windows, Cocoa on macOS)
#   jelly::imgui      Dear ImGui core + imgui_impl_glfw + imgui_impl_opengl3 (the latter loads GL itself)
#   jelly::stb        stb_image, stb_image_write, stb_easy_font headers + their implementation
#   jelly::gl_headers GL/glcorearb.h and KHR/khrplatform.h (types and constants: framework/render loads
#                     GL functions at run time through glfwGetProcAddress, so no loader library)

# ---- GLFW ----------------------------------------------------------------------------------------
if(JELLY_DEPS_SYSTEM)
  find_package(glfw3 3.3 CONFIG QUIET)
  if(NOT TARGET glfw AND PKG_CONFIG_FOUND)
    pkg_check_modules(JELLY_GLFW QUIET IMPORTED_TARGET glfw3)
    if(TARGET PkgConfig::JELLY_GLFW)
      jelly_dep_alias(glfw PkgConfig::JELLY_GLFW)
      set(glfw3_DIR "pkg-config glfw3 ${JELLY_GLFW_VERSION}")
    endif()
  endif()
endif()
if(TARGET glfw)
  jelly_dep_report(GLFW "system package ${glfw3_DIR}")
else()
  jelly_dep_bundle(dir glfw include/GLFW/glfw3.h)
  if(NOT dir)
    jelly_dep_missing(GLFW libglfw3-dev glfw)
  endif()
  # Bundled GLFW 3.3 on Linux/BSD builds its X11 backend (a Wayland desktop runs it through
  # XWayland), which needs the X11 development headers; without them GLFW stops the configure with
  # "Could NOT find X11 (missing: X11_X11_INCLUDE_PATH X11_X11_LIB)", which names no package. A
  # student would rather have everything else: the viewer is turned off for this configure (a
  # normal variable over the cache option, so the next configure after installing the packages
  # turns it back on) with a warning that names the packages. tests/deps (x11_missing) checks it.
  if(NOT WIN32 AND NOT APPLE AND NOT GLFW_USE_WAYLAND)
    find_package(X11 QUIET)
    set(missing_x11)
    if(NOT X11_X11_INCLUDE_PATH OR NOT X11_X11_LIB OR NOT X11_Xkb_INCLUDE_PATH)
      list(APPEND missing_x11 X11)
    endif()
    foreach(part Xrandr Xinerama Xcursor Xi)   # the extensions GLFW's CMakeLists requires
      if(NOT X11_${part}_INCLUDE_PATH)
        list(APPEND missing_x11 ${part})
      endif()
    endforeach()
    if(missing_x11)
      string(REPLACE ";" ", " missing_x11 "${missing_x11}")
      message(WARNING "Jelly Lab: the viewer is OFF for this build: the X11 development headers "
        "that the bundled GLFW needs are not installed (missing: ${missing_x11}).\n"
        "Everything else builds as usual: the jelly command line, the unit tests, the self-check.\n"
        "To get the viewer (jelly-lab, jelly render), install them and run the same cmake command again:\n"
        "  Debian/Ubuntu: sudo apt-get install libx11-dev libxrandr-dev libxinerama-dev libxcursor-dev libxi-dev\n"
        "  Fedora:        sudo dnf install libX11-devel libXrandr-devel libXinerama-devel libXcursor-devel libXi-devel\n"
        "  Arch:          sudo pacman -S libx11 libxrandr libxinerama libxcursor libxi\n"
        "(On a Wayland desktop too: the viewer runs through XWayland.) "
        "To build without the viewer and without this warning: -DJELLY_BUILD_VIEWER=OFF.")
      set(JELLY_BUILD_VIEWER OFF)
      set(JELLY_VIEWER_OFF_REASON "X11 development headers missing (${missing_x11})")
      return()
    endif()
  endif()
  set(GLFW_BUILD_DOCS OFF CACHE BOOL "")
  set(GLFW_BUILD_TESTS OFF CACHE BOOL "")
  set(GLFW_BUILD_EXAMPLES OFF CACHE BOOL "")
  set(GLFW_INSTALL OFF CACHE BOOL "")
  add_subdirectory(${dir} ${PROJECT_BINARY_DIR}/third_party/glfw EXCLUDE_FROM_ALL)
  jelly_dep_report(GLFW "bundled ${dir} (built here)")
endif()

# ---- GL headers ------------------------------------------------------------------------------------
# (Cached search results are used only when system packages are allowed: a build folder switched
# to JELLY_DEPS=bundled must not keep a path found before.)
set(gl_include "")
if(JELLY_DEPS_SYSTEM)
  find_path(JELLY_GLCOREARB_INCLUDE GL/glcorearb.h)
  if(JELLY_GLCOREARB_INCLUDE AND EXISTS ${JELLY_GLCOREARB_INCLUDE}/KHR/khrplatform.h)
    set(gl_include ${JELLY_GLCOREARB_INCLUDE})
  endif()
endif()
add_library(jelly_dep_gl_headers INTERFACE)
add_library(jelly::gl_headers ALIAS jelly_dep_gl_headers)
if(gl_include)
  target_include_directories(jelly_dep_gl_headers SYSTEM INTERFACE ${gl_include})
  jelly_dep_report("GL headers" "system ${gl_include}/GL/glcorearb.h")
else()
  jelly_dep_bundle(dir khronos include/GL/glcorearb.h)
  if(NOT dir)
    jelly_dep_missing("GL headers (GL/glcorearb.h)" libgl-dev khronos)
  endif()
  target_include_directories(jelly_dep_gl_headers SYSTEM INTERFACE ${dir}/include)
  jelly_dep_report("GL headers" "bundled ${dir}")
endif()

# ---- stb -------------------------------------------------------------------------------------------
set(dir "")
if(JELLY_DEPS_SYSTEM)
  find_path(JELLY_STB_INCLUDE stb_image_write.h PATH_SUFFIXES stb)
  if(JELLY_STB_INCLUDE AND EXISTS ${JELLY_STB_INCLUDE}/stb_easy_font.h AND EXISTS ${JELLY_STB_INCLUDE}/stb_image.h)
    set(dir ${JELLY_STB_INCLUDE})
  endif()
endif()
if(dir)
  jelly_dep_report(stb "system ${dir}")
else()
  jelly_dep_bundle(dir stb stb_image_write.h)
  if(NOT dir)
    jelly_dep_missing(stb libstb-dev stb)
  endif()
  jelly_dep_report(stb "bundled ${dir}")
endif()
# The implementation is compiled here in both cases (header-only library; one definition).
add_library(jelly_dep_stb STATIC ${CMAKE_CURRENT_LIST_DIR}/deps/stb_implementation.cpp)
target_include_directories(jelly_dep_stb SYSTEM PUBLIC ${dir})
add_library(jelly::stb ALIAS jelly_dep_stb)

# ---- Dear ImGui --------------------------------------------------------------------------------------
# Debian's libimgui-dev is the core as a library; its GLFW/OpenGL 3 backends are shipped as example
# sources (possibly gzipped): copied or unpacked into the build tree at configure time.
set(JELLY_IMGUI_BACKENDS_DIR /usr/share/doc/libimgui-dev/examples/backends CACHE PATH
    "Folder with Dear ImGui's imgui_impl_glfw.cpp and imgui_impl_opengl3.cpp (system ImGui only)")
set(imgui_sources)
if(JELLY_DEPS_SYSTEM AND PKG_CONFIG_FOUND)
  pkg_check_modules(JELLY_IMGUI QUIET IMPORTED_TARGET imgui)
endif()
if(TARGET PkgConfig::JELLY_IMGUI)
  foreach(name imgui_impl_glfw.cpp imgui_impl_opengl3.cpp)
    set(out ${PROJECT_BINARY_DIR}/imgui_backends/${name})
    if(EXISTS ${JELLY_IMGUI_BACKENDS_DIR}/${name})
      configure_file(${JELLY_IMGUI_BACKENDS_DIR}/${name} ${out} COPYONLY)
    elseif(EXISTS ${JELLY_IMGUI_BACKENDS_DIR}/${name}.gz)
      execute_process(COMMAND gzip -dc ${JELLY_IMGUI_BACKENDS_DIR}/${name}.gz OUTPUT_FILE ${out}
                      RESULT_VARIABLE rc)
      if(NOT rc EQUAL 0)
        message(FATAL_ERROR "cannot unpack ${JELLY_IMGUI_BACKENDS_DIR}/${name}.gz")
      endif()
    else()
      message(FATAL_ERROR "Dear ImGui backend ${name} not found in ${JELLY_IMGUI_BACKENDS_DIR} "
                          "(install libimgui-dev, set JELLY_IMGUI_BACKENDS_DIR, or use -DJELLY_DEPS=bundled)")
    endif()
    list(APPEND imgui_sources ${out})
  endforeach()
  set(imgui_includes ${JELLY_IMGUI_INCLUDEDIR}/backends)
  set(imgui_core PkgConfig::JELLY_IMGUI)
  jelly_dep_report("Dear ImGui" "system pkg-config imgui ${JELLY_IMGUI_VERSION}, backends from ${JELLY_IMGUI_BACKENDS_DIR}")
else()
  jelly_dep_bundle(dir imgui imgui.h)
  if(NOT dir)
    jelly_dep_missing("Dear ImGui" libimgui-dev imgui)
  endif()
  foreach(name imgui.cpp imgui_draw.cpp imgui_tables.cpp imgui_widgets.cpp imgui_demo.cpp
               backends/imgui_impl_glfw.cpp backends/imgui_impl_opengl3.cpp)
    list(APPEND imgui_sources ${dir}/${name})
  endforeach()
  set(imgui_includes ${dir} ${dir}/backends)
  set(imgui_core)
  jelly_dep_report("Dear ImGui" "bundled ${dir}")
endif()
add_library(jelly_dep_imgui STATIC ${imgui_sources})
target_include_directories(jelly_dep_imgui SYSTEM PUBLIC ${imgui_includes})
target_link_libraries(jelly_dep_imgui PUBLIC ${imgui_core} glfw ${CMAKE_DL_LIBS})
add_library(jelly::imgui ALIAS jelly_dep_imgui)
