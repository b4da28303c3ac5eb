#pragma once
/// \file step_pacer.h
/// How many fixed steps each frame of the Frog tab runs at a chosen speed (⅛ … 4 times real
/// time). Slow motion never shrinks the step: it steps once every few frames, so a run at ⅛
/// goes through exactly the states of a run at 1 — the seed stays Annex II to the bit. Fast
/// runs several steps in a frame. A scene whose step is more work than a frame holds
/// (FrogCanvas::kFrameWork) slows everything by that factor as well, and is never run faster
/// than one step a frame.

#include <array>

namespace granota {

class StepPacer {
public:
    /// The speeds offered, as multiples of real time (60 steps a second).
    static constexpr std::array<double, 6> kSpeeds{0.125, 0.25, 0.5, 1, 2, 4};

    /// One of kSpeeds; anything else is refused (false) and nothing changes.
    bool setSpeed(double speed);
    double speed() const { return m_speed; }
    /// The counted work of a step (Simulation::workPerStep) and what one frame holds: a step
    /// of more work takes ⌈work / frameWork⌉ frames, and fast runs only the steps a frame holds.
    void setWork(long work, long frameWork);

    /// Called once per frame: the steps to run in it (0 in the frames slow motion waits).
    int stepsThisFrame();
    /// Frames from one step to the next (1 unless slowed), and steps per frame (1 unless fast).
    int framesPerStep() const;
    int stepsPerFrame() const;
    /// The speed reached, steps per frame over frames per step: below speed() when the work
    /// slows it down.
    double effectiveSpeed() const { return double(stepsPerFrame()) / framesPerStep(); }
    /// Starts counting frames again (a new run steps on its first frame).
    void restart() { m_framesWaited = 0; }

private:
    double m_speed = 1;
    int m_workFrames = 1;   // frames one step's work takes
    long m_stepsAFrame = 1; // steps whose work one frame holds (≥ 1)
    int m_framesWaited = 0;
};

} // namespace granota
