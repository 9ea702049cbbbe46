// Breaks the rule on purpose (tests/CMakeLists.txt: architecture.details).
#include "io/swp/detail/lexer.hpp"
