/* Test plugin (plugin_driver_test.cpp, simulation_test.cpp): never returns from create, so the
 * host must give up after its start timeout, kill the child and report a hang at step 0. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <unistd.h>

#include "ego_plugin.h"

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  (void)config;
  for (;;) sleep(1000);
}

int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control) {
  (void)driver;
  (void)observation;
  control->acceleration = 0;
  control->steering_angle = 0;
  return 0;
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
