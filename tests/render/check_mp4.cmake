# cmake -DJELLY=… -DSCENE=… -DDIR=… -DFFPROBE=… -P check_mp4.cmake
# `jelly render` writes video.mp4 beside the PNGs when ffmpeg is on PATH: 0.2 s at 30 fps must give
# an H.264 video of 7 frames at 30 fps and 160×120. The frames folder has a space, quotes and a
# `$(...)` in its name: ffmpeg is started with an argument vector, no shell, so nothing is quoted.
file(REMOVE_RECURSE "${DIR}")
set(DIR "${DIR}/frames of Jo's \"jelly\" $(false)")
execute_process(COMMAND "${JELLY}" render "${SCENE}" --frames "${DIR}" --duration 0.2 --fps 30
                        --width 160 --height 120 --samples 0 --no-caption
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "jelly render failed (${rc}):\n${out}${err}")
endif()
if(NOT EXISTS "${DIR}/video.mp4")
  message(FATAL_ERROR "no ${DIR}/video.mp4 although ffmpeg is installed:\n${out}${err}")
endif()
execute_process(COMMAND "${FFPROBE}" -v error -select_streams v:0 -count_frames
                        -show_entries stream=codec_name,width,height,r_frame_rate,nb_read_frames
                        -of default=nw=1 "${DIR}/video.mp4"
                RESULT_VARIABLE rc OUTPUT_VARIABLE probe)
message(STATUS "video.mp4:\n${probe}")
foreach(expected "codec_name=h264" "width=160" "height=120" "r_frame_rate=30/1" "nb_read_frames=7")
  string(FIND "${probe}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "video.mp4: expected ${expected}")
  endif()
endforeach()
