#pragma once
// Parsing the small value formats the command line takes ("640x480",
// "1,2,3"); each throws InputError naming the option and what was expected.

#include <glm/glm.hpp>

#include <string>

namespace arcomp {

glm::ivec2 parseSize(const std::string& text, const std::string& option);
glm::vec3 parseVec3(const std::string& text, const std::string& option);

} // namespace arcomp
