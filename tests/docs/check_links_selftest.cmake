# check_links.cmake must be able to fail: a small tree whose links are all alive (a file, a folder,
# an anchor after a path, a web link, an in-page anchor, links inside code) must pass, and each
# planted dead link (a moved page, a wrong ../ depth from a handout, a missing figure) must be
# reported with its file and line.
#
#   cmake -DCHECK=<check_links.cmake> -DWORK=<scratch folder> -P check_links_selftest.cmake
cmake_minimum_required(VERSION 3.16)
file(REMOVE_RECURSE "${WORK}")
file(WRITE "${WORK}/docs/physics.md" "# Physics\n")
file(WRITE "${WORK}/assignments/a1/handout/figures/plot.png" "png")
file(WRITE "${WORK}/assignments/a1/handout/T1.md" "# T1\n")
file(WRITE "${WORK}/scenes/README.md" "[physics](../docs/physics.md)\n")
file(WRITE "${WORK}/README.md"
     "See [physics](docs/physics.md#springs), [scenes](scenes/), [web](https://example.org/x), [top](#top).\n"
     "```\n[not a link](nowhere.md)\n```\n`[code](nowhere.md)`\n")
file(WRITE "${WORK}/assignments/a1/handout/README.md"
     "[T1](T1.md) ![plot](figures/plot.png) [contract](../../../docs/physics.md)\n")

function(_check expect_ok out)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${WORK} -P ${CHECK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(expect_ok AND NOT rc EQUAL 0)
    message(FATAL_ERROR "check_links failed on a tree whose links are alive:\n${o}${e}")
  elseif(NOT expect_ok AND rc EQUAL 0)
    message(FATAL_ERROR "check_links passed a tree with planted dead links:\n${o}${e}")
  endif()
  set(${out} "${o}${e}" PARENT_SCOPE)
endfunction()

_check(TRUE output)

file(APPEND "${WORK}/assignments/a1/handout/README.md" "Read [Platforms](../platforms.md) first.\n")
file(APPEND "${WORK}/docs/physics.md" "\nThe [handout](handout/README.md).\n")
file(APPEND "${WORK}/README.md" "| a | ![fig](assignments/a1/handout/figures/missing.png) |\n")
_check(FALSE output)
foreach(where IN ITEMS "assignments/a1/handout/README.md:2: links to ../platforms.md"
                       "docs/physics.md:3: links to handout/README.md"
                       "README.md:6: links to assignments/a1/handout/figures/missing.png")
  string(FIND "${output}" "${where}" at)
  if(at LESS 0)
    message(FATAL_ERROR "check_links did not report ${where}\n${output}")
  endif()
endforeach()
string(REGEX MATCHALL ": links to " reported "${output}")
list(LENGTH reported count)
if(NOT count EQUAL 3)
  message(FATAL_ERROR "check_links reported ${count} dead links, 3 were planted:\n${output}")
endif()
message(STATUS "check_links: the 3 planted dead links reported with file and line; the good tree passes")
