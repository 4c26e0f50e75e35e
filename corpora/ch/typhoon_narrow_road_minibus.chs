# The grammar's worked example made a test: a minibus on a narrow two-lane road in a typhoon,
# a bus coming the other way and a boy who steps out from the pavement ahead.
import from MAP
  length: 500
  width: 40
RoadNetwork
  road → name narrow_road
    left boundary: (0.0, 23.25) (500.0, 23.25)
    center lines: (0.0, 20.0) (500.0, 20.0)
    right boundary: (0.0, 16.75) (500.0, 16.75)
Weather
  cloudiness: 1.0
  wetness: 1.0
  air_pressure: 0.96
  precipitation: 0.9
  wind_intensity: 1.0
  visibility: 0.5
NaturalDisaster
  MeteorologicalDisaster
    typhoon: 1
SpecialHighRisk
  wade: 0
Entity
  StaticEntity1
    name: pedestrians
    overview: little boy
  DynamicEntity1
    name: minibus
    timestamp: 2022 年 1 月 30 日 17:30:42
    speed: 30.0
    acceleration: 0.0
    track: curve to the east
    aim: The First People's Hospital
    position: (40.0, 18.4)
  DynamicEntity2
    name: bus
    timestamp: 2022 年 1 月 30 日 17:30:42
    speed: 40.0
    acceleration: 0.0
    track: oncoming, to the west
    position: (260.0, 21.6)
  DynamicEntity3
    name: boy
    timestamp: 2022 年 1 月 30 日 17:30:42
    speed: 6.0
    acceleration: 0.0
    track: crossing the road
    position: (110.0, 15.5)
ConstraintList
  constraint1 relate with minibus, current_vehicle
    safety_protocol: (wiper = true) && (lighton = true)
  constraint2 relate with minibus, forward_vehicle
    safety_protocol: ((dist > safedistance) = true) && (emergencybreak = false)
