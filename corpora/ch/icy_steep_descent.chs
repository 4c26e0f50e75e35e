# An icy mountain road going down: a loaded truck crawls ahead of the car, a van comes up the
# other way. On ice every vehicle brakes and corners with a fraction of its dry grip.
import from MAP
  length: 600
  width: 60
RoadNetwork
  road → name mountain_road
    left boundary: (0.0, 33.5) (200.0, 33.5) (400.0, 28.5) (600.0, 28.5)
    center lines: (0.0, 30.0) (200.0, 30.0) (400.0, 25.0) (600.0, 25.0)
    right boundary: (0.0, 26.5) (200.0, 26.5) (400.0, 21.5) (600.0, 21.5)
Weather
  cloudiness: 0.8
  wetness: 0.3
  precipitation: 0.0
  visibility: 0.9
SpecialHighRisk
  rough: 0
  iceRoad: 1
  steepDescentAhead: 1
  muddy: 0
  wade: 0
Entity
  DynamicEntity1
    name: car
    timestamp: 2023-01-12 07:45:00
    speed: 30.0
    acceleration: 0.0
    track: east, down the mountain
    position: (30.0, 28.3)
  DynamicEntity2
    name: truck
    timestamp: 2023-01-12 07:45:00
    speed: 15.0
    acceleration: 0.0
    track: ahead, east
    position: (110.0, 28.3)
  DynamicEntity3
    name: van
    timestamp: 2023-01-12 07:45:00
    speed: 35.0
    acceleration: 0.0
    track: oncoming
    position: (420.0, 26.7)
ConstraintList
  constraint1 relate with car, forward_vehicle
    safety_protocol: (dist > safedistance) && not emergencybreak
