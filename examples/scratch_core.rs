use nalgebra::Vector2;
use pistonslap::dynamics::testbeds::DoublePendulum;
use pistonslap::dynamics::*;
fn main() {
    for &step in &[4e-3, 2e-3, 1e-3] {
        let p = DoublePendulum { masses: [1.0, 1.0], lengths: [1.0, 1.0], gravity: 9.81, wall: -0.3, restitution: 1.0 };
        let q0 = Vector2::new(0.6, 0.9);
        let e0 = p.energy(&q0, &Vector2::zeros());
        let mut s = Stepper::new(p, 0.0, q0, Vector2::zeros(), StepperOptions { step, ..Default::default() }).unwrap();
        let t = std::time::Instant::now();
        let mut n = 0; let mut maxgap: f64 = 0.0; let mut maxdrift: f64 = 0.0;
        while n < 1000 {
            let tt = s.time() + 1.0;
            s.advance(tt).unwrap();
            for ev in s.events() { n += 1; maxgap = maxgap.max(s.system().gaps(ev.time, &ev.q)[0].abs()); }
            s.clear_events();
            let e = s.system().energy(s.position(), s.velocity());
            maxdrift = maxdrift.max(((e - e0) / e0).abs());
        }
        println!("step {step}: {n} events by t={} maxgap {maxgap:e} drift {maxdrift:e} in {:?}", s.time(), t.elapsed());
    }
}
