/* Test plugin (plugin_driver_test.cpp): answers its first step, then reports error 7. */
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
  control->acceleration = 0;
  control->steering_angle = 0;
  return ++self->steps >= 2 ? 7 : 0;
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
