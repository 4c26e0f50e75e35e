# A wet town street with two lanes each way: a van parked in the kerb lane may pull out into the
# car's lane as the car comes near (it does three times in ten), and a bus ahead may stop.
import from MAP
  length: 500
  width: 40
RoadNetwork
  road → name high_street
    left boundary: (0.0, 27.0) (500.0, 27.0)
    center lines: (0.0, 20.0) (500.0, 20.0)
    right boundary: (0.0, 13.0) (500.0, 13.0)
Weather
  cloudiness: 0.8
  wetness: 0.7
  precipitation: 0.4
  visibility: 0.9
Entity
  StaticEntity1
    name: van
    overview: a delivery van parked at the kerb
    position: (140.0, 14.8)
  DynamicEntity1
    name: car
    timestamp: 2023-10-09 17:45:00
    speed: 45.0
    acceleration: 0.0
    track: east
    position: (40.0, 18.2)
  DynamicEntity2
    name: bus
    timestamp: 2023-10-09 17:45:00
    speed: 35.0
    acceleration: 0.0
    track: ahead, east
    position: (100.0, 14.8)
ConstraintList
  constraint1 relate with van, car
    safety_protocol: not emergencybreak
    event: when dist < 30 do parked = false; position++
    probability: 0.3
  constraint2 relate with bus, car
    event: when wait > 6 do parked = true
    probability: 0.5
