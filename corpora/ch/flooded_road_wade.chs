# A flooded dip on a muddy road: a car has stalled in the water in the ego's lane, and a tractor
# trailer comes the other way through the flood. The driver must wade slowly.
import from MAP
  length: 500
  width: 40
RoadNetwork
  road → name river_road
    left boundary: (0.0, 23.5) (500.0, 23.5)
    center lines: (0.0, 20.0) (500.0, 20.0)
    right boundary: (0.0, 16.5) (500.0, 16.5)
Weather
  cloudiness: 1.0
  wetness: 1.0
  precipitation: 0.5
  visibility: 0.7
SpecialHighRisk
  muddy: 1
  wade: 1
Entity
  StaticEntity1
    name: stalled_car
    overview: a car stalled in the water
    position: (160.0, 18.3)
  DynamicEntity1
    name: ego
    timestamp: 2023-08-03 09:00:00
    speed: 20.0
    acceleration: 0.0
    track: east
    position: (40.0, 18.2)
  DynamicEntity2
    name: truck
    timestamp: 2023-08-03 09:00:00
    speed: 25.0
    acceleration: 0.0
    track: oncoming
    position: (300.0, 21.8)
ConstraintList
  constraint1 relate with ego, stalled_car
    safety_protocol: not (speed > 40)
