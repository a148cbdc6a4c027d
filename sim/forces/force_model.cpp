#include "sim/forces/force_model.h"

#include "sim/forces/force_models.h"

namespace forcelab::sim {

VectorX scaleFactors(ForceScale scale, const BallState& balls)
{
    switch (scale) {
    case ForceScale::None:
        return VectorX::Ones(balls.size());
    case ForceScale::Radius:
        return kReferenceRadius * balls.radius.cwiseInverse();
    case ForceScale::Mass:
        return sphereMass(kReferenceRadius) * balls.inverseMass;
    }
    return VectorX::Ones(balls.size());
}

ForceModel::ForceModel(const WorldSettings& settings, const BallState& balls, const StepInputs& inputs)
    : m_settings(settings)
    , m_balls(balls)
    , m_inputs(inputs)
{
    if (settings.wind.mode != WindMode::Off)
        m_windScale = scaleFactors(settings.wind.scale, balls);
    if (settings.point.enabled && settings.point.scale != ForceScale::None)
        m_pointScale = scaleFactors(settings.point.scale, balls);
    if (settings.drag.enabled && settings.drag.scale != ForceScale::None)
        m_dragScale = scaleFactors(settings.drag.scale, balls);
    for (const ForceModelInfo& model : forceModels())
        if (model.on(settings)) {
            m_active.push_back(&model);
            m_velocityIndependent = m_velocityIndependent && !model.velocityDependent;
        }
    if (balls.anyPinned())
        for (Eigen::Index i = 0; i < balls.size(); ++i)
            if (balls.pinned[static_cast<std::size_t>(i)])
                m_pinned.push_back(i);
}

double ForceModel::windAt(double t) const
{
    return m_inputs.wind.at(m_settings.wind.mode, m_settings.wind, t);
}

void ForceModel::acceleration(const Matrix2X& x, const Matrix2X& v, double t, Matrix2X& a) const
{
    ++m_evaluations;
    a.setZero(2, x.cols());
    const ForceContext c{m_settings, m_balls, m_inputs, m_windScale, m_pointScale, m_dragScale};
    for (const ForceModelInfo* model : m_active) // a model that is off is never called
        model->add(c, x, v, t, a);
    for (const Eigen::Index i : m_pinned) // every integrator then keeps a pinned ball where it is
        a.col(i).setZero();
}

void ForceModel::addOne(const ForceModelInfo& model, const Matrix2X& x, const Matrix2X& v, double t, Matrix2X& a) const
{
    const ForceContext c{m_settings, m_balls, m_inputs, m_windScale, m_pointScale, m_dragScale};
    model.add(c, x, v, t, a);
    for (const Eigen::Index i : m_pinned)
        a.col(i).setZero();
}

double ForceModel::potential(const Matrix2X& x) const
{
    const ForceContext c{m_settings, m_balls, m_inputs, m_windScale, m_pointScale, m_dragScale};
    double u = 0.0;
    for (const ForceModelInfo* model : m_active)
        if (model->potential)
            u += model->potential(c, x);
    return u;
}

const char* nonConstantAccelerationReason(const WorldSettings& s)
{
    for (const ForceModelInfo& model : forceModels())
        if (model.on(s) && model.notConstant)
            if (const char* why = model.notConstant(s))
                return why;
    return nullptr;
}

} // namespace forcelab::sim
