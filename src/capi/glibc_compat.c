/* Older glibc for the Linux x86_64 build of hedge_c, so that one libhedge_c.so built on a new system
 * (Debian 12, glibc 2.36) loads on the distributions the Unity editor supports (Ubuntu 20.04:
 * glibc 2.31, libstdc++ of GCC 10).
 *
 * libstdc++ is linked into hedge_c statically (src/capi/CMakeLists.txt): the library needs
 * libstdc++ symbols that GCC 10's lacks (std::from_chars and std::to_chars for floats). What is
 * left are references to glibc functions whose default version is newer than 2.31, made by
 * hedge's code and by libstdc++.a. Each is rerouted here with the linker's --wrap (every reference
 * to NAME in every object of the link becomes __wrap_NAME) to a version every x86_64 glibc has
 * (GLIBC_2.2.5, the first), or to an equivalent. tests/capi/check_glibc.cmake reads the built
 * library's symbol versions and fails above GLIBC_2.31, naming the symbols, so a new reference
 * that raises the minimum is caught.
 *
 * The .symver directives bind a local name to one version of a glibc symbol: a call to the local
 * name is a call to that version. */
#define _GNU_SOURCE
#include <limits.h> /* any C library header: it defines __GLIBC__ under glibc */

#if defined(__x86_64__) && defined(__GLIBC__)

#include <errno.h>
#include <pthread.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/random.h>
#include <sys/stat.h>

#define HEDGE_COMPAT __attribute__((visibility("hidden")))

/* hypot: glibc 2.35 gave it a new version (a faster implementation, the same correctly rounded
 * results within its documented error); the old one computes the same function. */
double hedge_glibc_hypot(double, double);
__asm__(".symver hedge_glibc_hypot, hypot@GLIBC_2.2.5");
HEDGE_COMPAT double __wrap_hypot(double x, double y) { return hedge_glibc_hypot(x, y); }

/* stat, lstat, fstat, fstat64: functions of their own since glibc 2.33; before, the header turned
 * them into __xstat(_STAT_VER, ...), which every glibc still exports. _STAT_VER is 1 on x86_64
 * (_STAT_VER_LINUX), and struct stat and struct stat64 are the same there. */
enum { hedge_stat_ver = 1 };
int hedge_glibc_xstat(int, const char*, struct stat*);
int hedge_glibc_lxstat(int, const char*, struct stat*);
int hedge_glibc_fxstat(int, int, struct stat*);
__asm__(".symver hedge_glibc_xstat, __xstat@GLIBC_2.2.5");
__asm__(".symver hedge_glibc_lxstat, __lxstat@GLIBC_2.2.5");
__asm__(".symver hedge_glibc_fxstat, __fxstat@GLIBC_2.2.5");
HEDGE_COMPAT int __wrap_stat(const char* path, struct stat* st) {
  return hedge_glibc_xstat(hedge_stat_ver, path, st);
}
HEDGE_COMPAT int __wrap_lstat(const char* path, struct stat* st) {
  return hedge_glibc_lxstat(hedge_stat_ver, path, st);
}
HEDGE_COMPAT int __wrap_fstat(int fd, struct stat* st) { return hedge_glibc_fxstat(hedge_stat_ver, fd, st); }
HEDGE_COMPAT int __wrap_fstat64(int fd, struct stat* st) {
  return hedge_glibc_fxstat(hedge_stat_ver, fd, st);
}

/* The pthread functions: glibc 2.34 moved them from libpthread into libc under a new version and
 * kept the old one, GLIBC_2.2.5, which older glibc's libpthread.so.0 defines (src/capi/CMakeLists.txt
 * makes libhedge_c.so need libpthread.so.0, so that it is loaded there). */
#define HEDGE_OLD_PTHREAD(ret, name, params, args)                 \
  ret hedge_glibc_##name params;                                   \
  __asm__(".symver hedge_glibc_" #name ", " #name "@GLIBC_2.2.5"); \
  HEDGE_COMPAT ret __wrap_##name params { return hedge_glibc_##name args; }
HEDGE_OLD_PTHREAD(int, pthread_create, (pthread_t * t, const pthread_attr_t* a, void* (*f)(void*), void* p),
                  (t, a, f, p))
HEDGE_OLD_PTHREAD(int, pthread_join, (pthread_t t, void** r), (t, r))
HEDGE_OLD_PTHREAD(int, pthread_detach, (pthread_t t), (t))
HEDGE_OLD_PTHREAD(int, pthread_once, (pthread_once_t * o, void (*f)(void)), (o, f))
HEDGE_OLD_PTHREAD(int, pthread_key_create, (pthread_key_t * k, void (*d)(void*)), (k, d))
HEDGE_OLD_PTHREAD(int, pthread_key_delete, (pthread_key_t k), (k))
HEDGE_OLD_PTHREAD(void*, pthread_getspecific, (pthread_key_t k), (k))
HEDGE_OLD_PTHREAD(int, pthread_setspecific, (pthread_key_t k, const void* v), (k, v))
HEDGE_OLD_PTHREAD(int, pthread_rwlock_rdlock, (pthread_rwlock_t * l), (l))
HEDGE_OLD_PTHREAD(int, pthread_rwlock_wrlock, (pthread_rwlock_t * l), (l))
HEDGE_OLD_PTHREAD(int, pthread_rwlock_unlock, (pthread_rwlock_t * l), (l))
/* __pthread_key_create: libstdc++'s test whether threads are linked in (a weak reference). */
HEDGE_OLD_PTHREAD(int, __pthread_key_create, (pthread_key_t * k, void (*d)(void*)), (k, d))

/* __libc_single_threaded (glibc 2.32): libstdc++ reads it to skip atomic operations in a process
 * that never started a thread. Read as 0 here, "there may be threads", it always takes the atomic
 * path, which is right in every process; a host such as the Unity editor runs threads anyway. */
HEDGE_COMPAT char __wrap___libc_single_threaded = 0;

/* arc4random (glibc 2.36): referenced by libstdc++.a's std::random_device, which libstdc++'s own
 * string instantiations pull into the link; hedge never makes a random_device. Should anything
 * call it, the kernel's random bytes (getrandom, glibc 2.25) are what arc4random returns too. */
HEDGE_COMPAT uint32_t __wrap_arc4random(void) {
  uint32_t value = 0;
  unsigned char* p = (unsigned char*)&value;
  size_t got = 0;
  while (got < sizeof value) {
    const ssize_t n = getrandom(p + got, sizeof value - got, 0);
    if (n > 0)
      got += (size_t)n;
    else if (n < 0 && errno != EINTR)
      break;
  }
  return value;
}

#else
/* Not x86_64 glibc: nothing to reroute (ISO C wants a translation unit to declare something). */
typedef int hedge_glibc_compat_unused;
#endif
