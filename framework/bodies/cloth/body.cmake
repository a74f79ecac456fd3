# The cloth (A2, the cloth contract): body.type = "cloth".
jelly_body_kind(cloth ORDER 30 MODULE cloth_kind
                SOURCES cloth_kind.cpp cloth.cpp spheres.cpp cloth_physics.cpp cloth_probe.cpp cloth_study.cpp
                        cloth_summary.cpp)
