// The one definition of the stb functions Jelly Lab uses (stb is header-only: exactly one
// translation unit defines the *_IMPLEMENTATION macros). Built by cmake/JellyDepsViewer.cmake into
// jelly::stb, from the system's or the bundled stb headers alike. stb_easy_font is all static.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
