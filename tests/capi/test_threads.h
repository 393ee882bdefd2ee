/* The C11 threads the C ABI tests use (thrd_create, thrd_join, thrd_yield): <threads.h> where the C
 * library has it, a thin layer over the Windows thread API (MinGW-w64's C runtime, msvcrt or UCRT,
 * ships no <threads.h>) or over POSIX threads (macOS's C library has none either) where it does
 * not. */
#ifndef HEDGE_TEST_THREADS_H
#define HEDGE_TEST_THREADS_H

#if defined(_WIN32)
#include <stdlib.h>
#define WIN32_LEAN_AND_MEAN
#include <windows.h>
/* <windows.h> defines these as nothing (16-bit pointer qualifiers); the tests use them as names. */
#undef near
#undef far

typedef HANDLE thrd_t;
typedef int (*thrd_start_t)(void*);
enum { thrd_success = 0, thrd_error = 2 };

/* The start function and its argument, handed to the new thread. */
typedef struct {
  thrd_start_t run;
  void* arg;
} hedge_test_thread_start;

static inline DWORD WINAPI hedge_test_thread_main(LPVOID p) {
  hedge_test_thread_start start = *(hedge_test_thread_start*)p;
  free(p);
  return (DWORD)start.run(start.arg);
}

static inline int thrd_create(thrd_t* thread, thrd_start_t run, void* arg) {
  hedge_test_thread_start* start = (hedge_test_thread_start*)malloc(sizeof *start);
  if (!start) return thrd_error;
  start->run = run;
  start->arg = arg;
  *thread = CreateThread(NULL, 0, hedge_test_thread_main, start, 0, NULL);
  if (!*thread) {
    free(start);
    return thrd_error;
  }
  return thrd_success;
}

static inline int thrd_join(thrd_t thread, int* result) {
  DWORD code = 0;
  if (WaitForSingleObject(thread, INFINITE) != WAIT_OBJECT_0 || !GetExitCodeThread(thread, &code))
    return thrd_error;
  CloseHandle(thread);
  if (result) *result = (int)code;
  return thrd_success;
}

static inline void thrd_yield(void) { SwitchToThread(); }
#elif defined(__APPLE__) || defined(HEDGE_TEST_PTHREADS)
#include <pthread.h>
#include <sched.h>
#include <stdint.h>
#include <stdlib.h>

typedef pthread_t thrd_t;
typedef int (*thrd_start_t)(void*);
enum { thrd_success = 0, thrd_error = 2 };

typedef struct {
  thrd_start_t run;
  void* arg;
} hedge_test_thread_start;

static inline void* hedge_test_thread_main(void* p) {
  hedge_test_thread_start start = *(hedge_test_thread_start*)p;
  free(p);
  return (void*)(intptr_t)start.run(start.arg);
}

static inline int thrd_create(thrd_t* thread, thrd_start_t run, void* arg) {
  hedge_test_thread_start* start = (hedge_test_thread_start*)malloc(sizeof *start);
  if (!start) return thrd_error;
  start->run = run;
  start->arg = arg;
  if (pthread_create(thread, NULL, hedge_test_thread_main, start) != 0) {
    free(start);
    return thrd_error;
  }
  return thrd_success;
}

static inline int thrd_join(thrd_t thread, int* result) {
  void* value = NULL;
  if (pthread_join(thread, &value) != 0) return thrd_error;
  if (result) *result = (int)(intptr_t)value;
  return thrd_success;
}

static inline void thrd_yield(void) { sched_yield(); }
#else
#include <threads.h>
#endif

#endif
