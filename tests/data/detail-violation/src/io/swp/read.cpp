// Allowed: the io layer includes its own detail/ headers.
#include "io/swp/detail/lexer.hpp"
