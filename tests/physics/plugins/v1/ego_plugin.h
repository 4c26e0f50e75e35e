/* A copy of physics/ego/ego_plugin.h as it was at ABI version 1, kept to build a version 1
 * plugin (version1.c) and test that scenfuzz still runs it. Do not update it.
 *
 * The C ABI through which another driver takes the ego's wheel (docs/ego-plugin.md).
 *
 * A plugin is a shared library exporting the three functions below. scenfuzz loads it in a
 * child process for each evaluation, so a plugin that crashes or hangs costs that evaluation
 * only. Every step (dt seconds of simulated time) the plugin gets an observation (its own
 * state, what its perception saw, the route ahead, the next traffic light and stop sign) and
 * returns a control (acceleration and front-wheel steering angle), which scenfuzz applies to
 * the ego with the kinematic bicycle model of its vehicle class.
 *
 * All structs are plain C with fixed-size arrays so that they cross a pipe unchanged; all
 * quantities are SI (m, s, m/s, m/s^2, rad) in the map's ENU frame, headings counter-clockwise
 * from east. Plain C99: this header must stay includable from C and C++. */
#ifndef SCENFUZZ_EGO_PLUGIN_H
#define SCENFUZZ_EGO_PLUGIN_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SCENFUZZ_EGO_ABI_VERSION 1
#define SCENFUZZ_MAX_OBJECTS 64
#define SCENFUZZ_ROUTE_POINTS 64

typedef struct scenfuzz_vehicle {
  double length, width, wheelbase;
  double max_speed, max_acceleration, max_deceleration;
  double max_steering_angle;
} scenfuzz_vehicle;

typedef struct scenfuzz_ego_config {
  uint32_t abi_version; /* SCENFUZZ_EGO_ABI_VERSION */
  double dt;            /* seconds per step */
  uint64_t seed;        /* for any randomness the driver has: use it, so runs repeat */
  scenfuzz_vehicle vehicle;
  double target_x, target_y; /* where the ego must go; NaN when the scenario gives no target */
} scenfuzz_ego_config;

typedef struct scenfuzz_ego_state {
  double time;
  double x, y, heading, speed, acceleration, yaw_rate, steering_angle;
} scenfuzz_ego_state;

enum scenfuzz_object_kind {
  SCENFUZZ_OBJECT_VEHICLE = 0,
  SCENFUZZ_OBJECT_PEDESTRIAN = 1,
  SCENFUZZ_OBJECT_OBSTACLE = 2
};

/* One perceived object: as the perception model saw it (noisy, possibly late). */
typedef struct scenfuzz_object {
  uint32_t id;   /* stable across steps */
  uint32_t kind; /* enum scenfuzz_object_kind */
  double x, y, heading, speed;
  double length, width;
} scenfuzz_object;

/* A point of the route's centre line ahead of the ego, about 2 m apart, the first one at the
 * ego's projection onto the route. */
typedef struct scenfuzz_route_point {
  double x, y, heading;
  double speed_limit; /* m/s */
} scenfuzz_route_point;

enum scenfuzz_light {
  SCENFUZZ_LIGHT_NONE = -1,
  SCENFUZZ_LIGHT_RED = 0,
  SCENFUZZ_LIGHT_YELLOW = 1,
  SCENFUZZ_LIGHT_GREEN = 2
};

typedef struct scenfuzz_observation {
  scenfuzz_ego_state ego;
  uint32_t object_count; /* nearest first, at most SCENFUZZ_MAX_OBJECTS */
  scenfuzz_object objects[SCENFUZZ_MAX_OBJECTS];
  uint32_t route_point_count;
  scenfuzz_route_point route[SCENFUZZ_ROUTE_POINTS];
  double distance_to_target; /* along the route; INFINITY without a target */
  int32_t light;             /* enum scenfuzz_light: the next signal on the route */
  double light_distance;     /* to its stop line; INFINITY when light is NONE */
  double stop_sign_distance; /* to the next stop sign's line on the route; INFINITY if none */
} scenfuzz_observation;

typedef struct scenfuzz_control {
  double acceleration;   /* m/s^2; negative brakes; clamped to the vehicle's limits */
  double steering_angle; /* rad, front wheel, positive left; clamped */
} scenfuzz_control;

/* Returns the driver's state, or NULL on failure (the evaluation is reported as failed). */
void* scenfuzz_ego_create(const scenfuzz_ego_config* config);
/* Fills `control`; returns 0, or non-zero on failure (the evaluation is reported as failed). */
int scenfuzz_ego_step(void* driver, const scenfuzz_observation* observation,
                      scenfuzz_control* control);
void scenfuzz_ego_destroy(void* driver);

#ifdef __cplusplus
}
#endif

#endif
