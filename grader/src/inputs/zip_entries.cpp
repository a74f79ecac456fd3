// The names of a zip's entries, read with libzip (class_archives.hpp).
#include <zip.h>
#include <stdexcept>

#include "inputs/class_archives.hpp"

namespace jelly::grade {

std::vector<std::string> zip_entry_names(const std::filesystem::path& zip,
                                         const std::string& shown) {
  int error = 0;
  zip_t* archive = zip_open(zip.string().c_str(), ZIP_RDONLY, &error);
  if (!archive) {
    zip_error_t why;
    zip_error_init_with_code(&why, error);
    const std::string message = zip_error_strerror(&why);
    zip_error_fini(&why);
    throw std::runtime_error(shown + ": not a zip file libzip can read (" + message + ")");
  }
  std::vector<std::string> names;
  const zip_int64_t count = zip_get_num_entries(archive, 0);
  for (zip_int64_t k = 0; k < count; ++k) {
    // ZIP_FL_ENC_RAW: the name as stored, so that the refusals name what the zip holds.
    const char* name = zip_get_name(archive, static_cast<zip_uint64_t>(k), ZIP_FL_ENC_RAW);
    if (name) names.emplace_back(name);
  }
  zip_discard(archive);
  return names;
}

}  // namespace jelly::grade
