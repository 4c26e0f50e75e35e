/* Test plugin (plugin_driver_test.cpp): never returns from its first step, so the host must
 * time out, kill the child and report the step. */
#include <stdlib.h>

#include "ego_plugin.h"

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  (void)config;
  return malloc(1);
}

int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control) {
  volatile unsigned long spins = 0;
  (void)driver;
  (void)observation;
  (void)control;
  for (;;) ++spins;
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
