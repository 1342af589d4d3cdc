#pragma once
//! The generator's exceptions are ctab/core/error.hpp's; this header includes it for the sources that name it here.
#include "ctab/core/error.hpp"
