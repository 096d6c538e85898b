; ProbeCycle program for grbl: the delay-stability test (ISO 230-10).
; The same surface touched repeatedly at several feeds along one axis and
; direction, each touch from far enough out to be at full speed. The lab fits
; the delay from the recorded positions.
; Every probing move searches past the farthest place its surface can be by
; more than the touch's stop (cycle.search_beyond_mm), and every later one
; covers the whole move back before it: the axis is never braking for the
; move's end when it touches.
; Plan ee042f037781f322 (keep the plan file: the import matches the positions to it).
; Date 2026-01-15.
; Scenario values and options used:
;   machine.accel_model = time_constant
;   machine.time_constant_s = 0.06
;   machine.max_accel_mm_s2 = 2000
;   machine.max_jerk_mm_s3 = 40000
;   machine.filter = none
;   machine.filter_time_s = 0.03
;   machine.servo_time_constant_s = 0
;   machine.scan_period_s = 0.004
;   machine.controller_latency_s = 0.002
;   probe.interface_delay_s = 0.002
;   probe.pretravel_mm = 0.005
;   probe.overtravel_limit_mm = 5
;   cycle.feed_override_max_pct = 120
;   cycle.probe_feed_mm_min = 2000
;   repeats = 2
;   margin_mm = 1
;   placement_mm = 10
; WARNING: prove this program out first at reduced feed override (its
; probing and return moves run at a feed) and reduced rapid override
; (its retracts and lifts are rapids), with the probe clear of the part,
; and check every move against your machine before a touch.
; Every move is incremental (G91) from where the probe stands when the program
; starts or a pause ends. A probing move that does not trigger stops the
; program.
; Positions: grbl answers [PRB:x,y,z:1] after each probe (machine
; positions; set $13=0 for mm). Save the sender's console to a file and
; import that file.
G21 G91 G94
; check: the probe stands in front of the surface, at most 10 mm from it, touching along X+; resume to start
M0
; Plan signature (plan ee042f037781f322): twice, G38.3 out along Z+ and back; grbl's
; [PRB:...:0] answers tell the import which plan ran. Free air needed: 0.970 mm along Z+.
G38.3 Z0.970 F300
G38.3 Z-0.870 F300
G1 Z-0.100 F300
G38.3 Z0.800 F300
G38.3 Z-0.700 F300
G1 Z-0.100 F300
; locate the surface at 30 mm/min
G38.2 X12.514 F30
G0 X-1.039 ; to 1.015 mm before the surface: room to reach 30 mm/min plus the margin
; touch 1: X+ at 30 mm/min, 1 of 2
G38.2 X3.553 F30
G0 X-1.039 ; to 1.015 mm before the surface: room to reach 30 mm/min plus the margin
; touch 2: X+ at 30 mm/min, 2 of 2
G38.2 X3.553 F30
G0 X-1.174 ; to 1.15 mm before the surface: room to reach 300 mm/min plus the margin
; touch 3: X+ at 300 mm/min, 1 of 2
G38.2 X3.791 F300
G0 X-1.345 ; to 1.15 mm before the surface: room to reach 300 mm/min plus the margin
; touch 4: X+ at 300 mm/min, 2 of 2
G38.2 X3.962 F300
G0 X-2.195 ; to 2 mm before the surface: room to reach 2000 mm/min plus the margin
; touch 5: X+ at 2000 mm/min, 1 of 2
G38.2 X5.458 F2000
G0 X-3.272 ; to 2 mm before the surface: room to reach 2000 mm/min plus the margin
; touch 6: X+ at 2000 mm/min, 2 of 2
G38.2 X6.535 F2000
G0 X-11.272 ; clear of the surface
G90
M2
