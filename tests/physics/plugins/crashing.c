/* Test plugin (plugin_driver_test.cpp): drives straight, then dereferences NULL on its third
 * step, so the host must report a SIGSEGV at step 3 and survive it. */
#include <stdlib.h>

#include "ego_plugin.h"

typedef struct counter {
  int steps;
} counter;

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  (void)config;
  return calloc(1, sizeof(counter));
}

int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control) {
  counter* self = driver;
  (void)observation;
  if (++self->steps == 3) {
    volatile int* nowhere = NULL;
    *nowhere = 1;
  }
  control->acceleration = 1;
  control->steering_angle = 0;
  return 0;
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
