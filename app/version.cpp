#include "shockgas/version.hpp"
