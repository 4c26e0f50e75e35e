# A landslide has buried the car's lane 120 m ahead; to pass, the car must use the oncoming lane,
# where a truck is coming down the valley.
import from MAP
  length: 600
  width: 40
RoadNetwork
  road → name valley_road
    left boundary: (0.0, 23.5) (600.0, 23.5)
    center lines: (0.0, 20.0) (600.0, 20.0)
    right boundary: (0.0, 16.5) (600.0, 16.5)
Weather
  cloudiness: 0.9
  wetness: 0.6
  precipitation: 0.3
  visibility: 0.8
NaturalDisaster
  GeologicalDisaster
    landslide: 1
Entity
  DynamicEntity1
    name: car
    timestamp: 2023-07-21 10:20:00
    speed: 40.0
    acceleration: 0.0
    track: east
    position: (40.0, 18.2)
  DynamicEntity2
    name: truck
    timestamp: 2023-07-21 10:20:00
    speed: 45.0
    acceleration: 0.0
    track: oncoming
    position: (330.0, 21.8)
ConstraintList
  constraint1 relate with car, forward_vehicle
    safety_protocol: (emergencybreak = false)
