// Root finders for relax flights: to be written (helper owns this file).
#include "relax_roots.hpp"
