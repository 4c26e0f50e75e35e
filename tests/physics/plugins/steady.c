/* Test plugin (reconstruct_command_test.cpp): an inattentive driver that holds its speed and its
 * wheel straight whatever it sees: the ego of a driver test that fails to avoid what it could. */
#include <stdlib.h>

#include "ego_plugin.h"

typedef struct nothing {
  int unused;
} nothing;

uint32_t scenfuzz_ego_abi_version(void) { return SCENFUZZ_EGO_ABI_VERSION; }

void* scenfuzz_ego_create(const scenfuzz_ego_config* config) {
  (void)config;
  return calloc(1, sizeof(nothing));
}

int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control) {
  (void)driver;
  (void)observation;
  control->acceleration = 0;
  control->steering_angle = 0;
  control->version = SCENFUZZ_EGO_ABI_VERSION;
  control->signals = 0;
  return 0;
}

void scenfuzz_ego_destroy(void* driver) { free(driver); }
