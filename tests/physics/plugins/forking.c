/* Test plugin (plugin_teardown_test.cpp): forks a sleeper from create (a process that would
 * outlive its evaluation unless the host ends the plugin's whole process group), then ends its
 * second step as config->seed % 4 says: 0 answers normally, 1 crashes (SIGSEGV), 2 hangs,
 * 3 returns error 5. Its first step answers with the sleeper's process id as the acceleration,
 * so that the test can watch the sleeper. The sleeper keeps the host's socket open, as any
 * child of a plugin does. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <unistd.h>

#include "ego_plugin.h"

typedef struct forking {
  int steps;
  int ending;
  pid_t sleeper;
} forking;

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  forking* self = calloc(1, sizeof(forking));
  self->ending = (int)(config->seed % 4);
  self->sleeper = fork();
  if (self->sleeper == 0) {
    sleep(600);
    _exit(0);
  }
  return self;
}

int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control) {
  forking* self = driver;
  (void)observation;
  control->acceleration = 0;
  control->steering_angle = 0;
  if (++self->steps < 2) {
    control->acceleration = (double)self->sleeper;
    return 0;
  }
  switch (self->ending) {
    case 1: {
      volatile int* nowhere = NULL;
      *nowhere = 1;
      return 0;
    }
    case 2:
      for (;;) sleep(1000);
    case 3: return 5;
    default: return 0;
  }
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
