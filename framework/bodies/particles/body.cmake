# Particles given one by one, with explicit springs (A1's spring and particle scenes):
# body.type = "particles".
jelly_body_kind(particles ORDER 20 MODULE particles_kind SOURCES particles_kind.cpp)
