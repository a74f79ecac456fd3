# cmake -DJELLY=… -DSCENE=… -DDIR=… -P check_mp4_fallbacks.cmake   (POSIX: a shell-script ffmpeg)
# `jelly render`'s MP4 step when it cannot make the video, with or without a real ffmpeg
# installed: the PNG frames are written and the exit code stays 0 in both cases.
#  1. No ffmpeg on PATH: "(no ffmpeg on PATH: PNG frames only …)" naming the package to install.
#  2. An ffmpeg that fails (exit 3): "ffmpeg failed (ffmpeg exited with code 3)" on stderr; the
#     fake records its arguments, which must be exactly the encoder's argument vector, one
#     argument each, the frames folder's space and quote included.
file(REMOVE_RECURSE "${DIR}")
set(frames_args --duration 0.1 --fps 30 --width 160 --height 120 --samples 0 --no-caption)

function(render frames path out_var err_var)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env "PATH=${path}" "${JELLY}" render "${SCENE}"
                          --frames "${frames}" ${frames_args}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "jelly render (PATH=${path}) exited ${rc}, expected 0:\n${out}${err}")
  endif()
  foreach(k 0 1 2 3)
    if(NOT EXISTS "${frames}/frame_0000${k}.png")
      message(FATAL_ERROR "no ${frames}/frame_0000${k}.png:\n${out}${err}")
    endif()
  endforeach()
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${err_var} "${err}" PARENT_SCOPE)
endfunction()

# 1. A PATH with no ffmpeg (an empty folder).
file(MAKE_DIRECTORY "${DIR}/empty-bin")
render("${DIR}/no-ffmpeg" "${DIR}/empty-bin" out err)
string(FIND "${out}" "(no ffmpeg on PATH: PNG frames only; for video.mp4, install ffmpeg: apt-get install ffmpeg" at)
if(at LESS 0)
  message(FATAL_ERROR "no ffmpeg: expected the message naming the package, got:\n${out}${err}")
endif()
if(EXISTS "${DIR}/no-ffmpeg/video.mp4")
  message(FATAL_ERROR "no ffmpeg, yet ${DIR}/no-ffmpeg/video.mp4 exists")
endif()

# 2. A failing ffmpeg that writes each argument it got on a line of its own.
set(bin "${DIR}/failing-bin")
file(MAKE_DIRECTORY "${bin}")
file(WRITE "${bin}/ffmpeg" "#!/bin/sh\nfor a in \"$@\"; do printf '%s\\n' \"$a\"; done > \"$0.args\"\nexit 3\n")
file(CHMOD "${bin}/ffmpeg" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ
     GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(frames "${DIR}/it's failing")
render("${frames}" "${bin}" out err)
string(FIND "${err}" "jelly render: ffmpeg failed (ffmpeg exited with code 3); the PNG frames are in ${frames}" at)
if(at LESS 0)
  message(FATAL_ERROR "failing ffmpeg: expected the failure on stderr, got:\n${out}${err}")
endif()
file(READ "${bin}/ffmpeg.args" got)
set(expected "-loglevel\nerror\n-y\n-framerate\n30\n-i\n${frames}/frame_%05d.png\n-vf\n"
             "pad=ceil(iw/2)*2:ceil(ih/2)*2\n-pix_fmt\nyuv420p\n-c:v\nlibx264\n${frames}/video.mp4\n")
string(CONCAT expected ${expected})
if(NOT got STREQUAL expected)
  message(FATAL_ERROR "ffmpeg's arguments, one a line:\n${got}\nexpected:\n${expected}")
endif()
message(STATUS "no ffmpeg and a failing ffmpeg: PNG frames, exit 0, the right message; ffmpeg got "
               "the argument vector unchanged")
