// SPDX-License-Identifier: Apache-2.0
/* fmi3PlatformTypes.h for ctab's FMU wrapper, written from the text of the Functional Mock-up Interface
 * Specification 3.0 (Modelica Association, 2022), section 2.2.2 "Platform Dependent Definitions": the base types of
 * the C interface and the opaque pointers exchanged with the importer. Binary FMUs must use these definitions. */
#ifndef fmi3PlatformTypes_h
#define fmi3PlatformTypes_h

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Opaque pointers: the FMU's instance, the importer's environment handed back in callbacks, a saved FMU state. */
typedef void* fmi3Instance;
typedef void* fmi3InstanceEnvironment;
typedef void* fmi3FMUState;

/* Handle of one variable value (scalar or array), as declared in modelDescription.xml. */
typedef uint32_t fmi3ValueReference;

/* The variable types ("numeric types" are all but fmi3Char, fmi3String, fmi3Byte, fmi3Binary and fmi3Clock). */
typedef float fmi3Float32;
typedef double fmi3Float64;
typedef int8_t fmi3Int8;
typedef uint8_t fmi3UInt8;
typedef int16_t fmi3Int16;
typedef uint16_t fmi3UInt16;
typedef int32_t fmi3Int32;
typedef uint32_t fmi3UInt32;
typedef int64_t fmi3Int64;
typedef uint64_t fmi3UInt64;
typedef bool fmi3Boolean;
typedef char fmi3Char;
typedef const fmi3Char* fmi3String;
typedef uint8_t fmi3Byte;
typedef const fmi3Byte* fmi3Binary;
typedef bool fmi3Clock;

#define fmi3True true
#define fmi3False false
#define fmi3ClockActive true
#define fmi3ClockInactive false

#endif /* fmi3PlatformTypes_h */
