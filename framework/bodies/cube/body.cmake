# The jelly cube (A1): body.type = "cube".
jelly_body_kind(cube ORDER 10 MODULE cube_kind
                SOURCES cube_kind.cpp cube.cpp cube_physics.cpp cube_probe.cpp cube_study.cpp course_scene.cpp)
