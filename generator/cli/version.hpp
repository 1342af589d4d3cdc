#pragma once
// Version and commit of this build (CMake passes them as definitions); "unknown" when built otherwise.
#ifndef CTAB_VERSION
#define CTAB_VERSION "unknown"
#endif
#ifndef CTAB_GIT_COMMIT
#define CTAB_GIT_COMMIT "unknown"
#endif
