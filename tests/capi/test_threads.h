/* The C11 threads the C ABI tests use (thrd_create, thrd_join, thrd_yield): <threads.h> where the C
 * library has it, a thin layer over the Windows thread API where it does not (MinGW-w64's C
 * runtime, msvcrt or UCRT, ships no <threads.h>). */
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
#else
#include <threads.h>
#endif

#endif
