#include "core/softbody/step_pacer.h"

#include <algorithm>
#include <cmath>

namespace granota {

bool StepPacer::setSpeed(double speed)
{
    if (std::find(kSpeeds.begin(), kSpeeds.end(), speed) == kSpeeds.end())
        return false;
    m_speed = speed;
    return true;
}

void StepPacer::setWork(long work, long frameWork)
{
    work = std::max(0L, work);
    frameWork = std::max(1L, frameWork);
    m_workFrames = static_cast<int>(std::max(1L, (work + frameWork - 1) / frameWork));
    m_stepsAFrame = work > 0 ? std::max(1L, frameWork / work) : frameWork;
}

int StepPacer::framesPerStep() const
{
    const int slow = m_speed < 1 ? static_cast<int>(std::lround(1 / m_speed)) : 1;
    return slow * m_workFrames;
}

int StepPacer::stepsPerFrame() const
{
    if (m_speed <= 1)
        return 1;
    return static_cast<int>(std::min<long>(std::lround(m_speed), m_stepsAFrame));
}

int StepPacer::stepsThisFrame()
{
    if (++m_framesWaited < framesPerStep())
        return 0;
    m_framesWaited = 0;
    return stepsPerFrame();
}

} // namespace granota
