// SPDX-License-Identifier: Apache-2.0
/* Fault injection for cli_security_test: preloaded (LD_PRELOAD) into ctab, it makes write, pwrite and writev to any
 * descriptor above 2 fail with ENOSPC once CTAB_ENOSPC_AFTER bytes have been written in the process, as a full
 * file system does. Standard output and error are left alone. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdlib.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

static long long bytes_left = -1;

/* 1 if `size` more bytes fit, else 0 with errno = ENOSPC. */
static int fits(size_t size) {
  if (bytes_left < 0) {
    const char* text = getenv("CTAB_ENOSPC_AFTER");
    bytes_left = text ? atoll(text) : (1LL << 62);
  }
  if ((long long)size > bytes_left) {
    bytes_left = 0;
    errno = ENOSPC;
    return 0;
  }
  bytes_left -= (long long)size;
  return 1;
}

ssize_t write(int fd, const void* data, size_t size) {
  static ssize_t (*real)(int, const void*, size_t);
  if (!real) real = (ssize_t (*)(int, const void*, size_t))dlsym(RTLD_NEXT, "write");
  if (fd > 2 && !fits(size)) return -1;
  return real(fd, data, size);
}

ssize_t pwrite(int fd, const void* data, size_t size, off_t offset) {
  static ssize_t (*real)(int, const void*, size_t, off_t);
  if (!real) real = (ssize_t (*)(int, const void*, size_t, off_t))dlsym(RTLD_NEXT, "pwrite");
  if (fd > 2 && !fits(size)) return -1;
  return real(fd, data, size, offset);
}

ssize_t pwrite64(int fd, const void* data, size_t size, off_t offset) { return pwrite(fd, data, size, offset); }

ssize_t writev(int fd, const struct iovec* parts, int count) {
  static ssize_t (*real)(int, const struct iovec*, int);
  if (!real) real = (ssize_t (*)(int, const struct iovec*, int))dlsym(RTLD_NEXT, "writev");
  size_t size = 0;
  for (int i = 0; i < count; ++i) size += parts[i].iov_len;
  if (fd > 2 && !fits(size)) return -1;
  return real(fd, parts, count);
}
