; ProbeCycle program for grbl: the ring-gauge calibration.
; 4 points in the bore with the spindle at 0 deg, the same 4 at 180 deg.
; The lab fits the ball radius and the stylus runout.
; Every probing move searches past the farthest place its surface can be by
; more than the touch's stop (cycle.search_beyond_mm), and every later one
; covers the whole move back before it: the axis is never braking for the
; move's end when it touches.
; Plan d6a2ab53fa11b3e2 (keep the plan file: the import matches the positions to it).
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
;   cycle.strategy = two_touch
;   cycle.probe_feed_mm_min = 2000
;   cycle.measure_feed_mm_min = 30
;   cycle.backoff_mm = 2
;   cycle.backoff_from = stop
;   cycle.return_feed_mm_min = 10000
;   gauge_diameter_mm = 50
;   ball_diameter_mm = 6
;   centre_tolerance_mm = 1
; WARNING: prove this program out first at reduced feed override (every
; move runs at a feed, none at the rapid), with the probe clear of the
; part, and check every move against your machine before a touch.
; Every move is incremental (G91) from where the probe stands when the program
; starts or a pause ends. A probing move that does not trigger stops the
; program.
; Positions: grbl answers [PRB:x,y,z:1] after each probe (machine
; positions; set $13=0 for mm). Save the sender's console to a file and
; import that file.
G21 G91 G94
; check: the spindle is oriented to 0 deg and the probe ball stands at the gauge centre (within 1 mm) at the measuring depth; resume to start
M0
; Plan signature (plan d6a2ab53fa11b3e2): twice, G38.3 out along Z+ and back; grbl's
; [PRB:...:0] answers tell the import which plan ran. Free air needed: 0.650 mm along Z+.
G38.3 Z0.650 F300
G38.3 Z-0.550 F300
G1 Z-0.100 F300
G38.3 Z0.320 F300
G38.3 Z-0.220 F300
G1 Z-0.100 F300
; X+ first touch at 2000 mm/min
G38.2 X26.263 F2000
G1 X-2.000 F10000 ; backoff
; touch 1: X+ measuring touch at 30 mm/min
G38.2 X4.514 F30
G1 X-22.024 F10000 ; back to the centre
; X- first touch at 2000 mm/min
G38.2 X-26.263 F2000
G1 X2.000 F10000 ; backoff
; touch 2: X- measuring touch at 30 mm/min
G38.2 X-4.514 F30
G1 X22.024 F10000 ; back to the centre
; Y+ first touch at 2000 mm/min
G38.2 Y26.263 F2000
G1 Y-2.000 F10000 ; backoff
; touch 3: Y+ measuring touch at 30 mm/min
G38.2 Y4.514 F30
G1 Y-22.024 F10000 ; back to the centre
; Y- first touch at 2000 mm/min
G38.2 Y-26.263 F2000
G1 Y2.000 F10000 ; backoff
; touch 4: Y- measuring touch at 30 mm/min
G38.2 Y-4.514 F30
G1 Y22.024 F10000 ; back to the centre
; turn the spindle to 180 deg; the probe stays at the gauge centre; resume
M0
; X+ first touch at 2000 mm/min
G38.2 X26.263 F2000
G1 X-2.000 F10000 ; backoff
; touch 5: X+ measuring touch at 30 mm/min
G38.2 X4.514 F30
G1 X-22.024 F10000 ; back to the centre
; X- first touch at 2000 mm/min
G38.2 X-26.263 F2000
G1 X2.000 F10000 ; backoff
; touch 6: X- measuring touch at 30 mm/min
G38.2 X-4.514 F30
G1 X22.024 F10000 ; back to the centre
; Y+ first touch at 2000 mm/min
G38.2 Y26.263 F2000
G1 Y-2.000 F10000 ; backoff
; touch 7: Y+ measuring touch at 30 mm/min
G38.2 Y4.514 F30
G1 Y-22.024 F10000 ; back to the centre
; Y- first touch at 2000 mm/min
G38.2 Y-26.263 F2000
G1 Y2.000 F10000 ; backoff
; touch 8: Y- measuring touch at 30 mm/min
G38.2 Y-4.514 F30
G1 Y22.024 F10000 ; back to the centre
G90
M2
