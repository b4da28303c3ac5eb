#include "ui/common/error_text.h"

#include "core/softbody/scenes/scene_parameters.h"
#include "core/softbody/scenes/stable_settings.h"
#include "ui/common/number_text.h"
#include "ui/common/language.h"

namespace granota::ui {

namespace {

/// The argument `i` of `error` as shown: a number in the interface's decimal sign, else its text.
QString arg(const Error& error, std::size_t i)
{
    if (i >= error.args.size())
        return QString();
    const MessageArg& a = error.args[i];
    return a.number ? displayNumber(*a.number) : QString::fromStdString(a.text);
}

} // namespace

QString ErrorText::parameterLabel(const std::string& key)
{
    const SceneParameter* param = findSceneParameter(key);
    if (!param || !*param->label)
        return QString::fromStdString(key);
    return QCoreApplication::translate(kParameterPanelContext, param->label).remove(QLatin1Char('&'));
}

QString ErrorText::of(const Error& error)
{
    const auto a = [&error](std::size_t i) { return arg(error, i); };
    const auto label = [&error](std::size_t i) { return i < error.args.size() ? parameterLabel(error.args[i].text) : QString(); };
    QString text;
    switch (error.id) {
    case MessageId::PointNotAPair:
        text = tr("point %1 is %2, not two numbers: write “x,y” with decimal points, “x;y” with decimal commas (as a "
                  "spreadsheet in Catalan saves it), or x and y separated by a tab; one point a line.")
                   .arg(a(0), a(1));
        break;
    case MessageId::CoordinateTooLong:
        text =
            tr("point %1: %2 is %3 characters long, more than %4, the longest number Granota reads.").arg(a(0), a(1), a(2), a(3));
        break;
    case MessageId::CoordinateNotANumber:
        text = tr("point %1: %2 = %3 is not a number (write integers, decimals or fractions p/q).").arg(a(0), a(1), a(2));
        break;
    case MessageId::CoordinateTooLarge:
        text = tr("point %1: %2 = %3 is too large (the largest double is about 1.8e308).").arg(a(0), a(1), a(2));
        break;
    case MessageId::CoordinateTooSmall: text = tr("point %1: %2 = %3 is too close to zero to read.").arg(a(0), a(1), a(2)); break;
    case MessageId::NoPointsGiven: text = tr("No points were given."); break;
    case MessageId::FileHoldsNoPoints: text = tr("The file holds no points."); break;
    case MessageId::TooManyPoints: text = tr("There are more than %1 points, the most Granota reads.").arg(a(0)); break;
    case MessageId::JsonPointsNotJson: text = tr("The text is not a JSON list of points [[x,y],…]."); break;
    case MessageId::JsonPointsNotAList: text = tr("The JSON text is %1, not a list of points [[x,y],…].").arg(a(0)); break;
    case MessageId::JsonPointNotAPair: text = tr("JSON point %1 is %2, not a pair [x,y].").arg(a(0), a(1)); break;
    case MessageId::SceneUnknownParameter: text = tr("The scene has no parameter %1.").arg(a(0)); break;
    case MessageId::SceneUnknownComponent:
        text = tr("The scene names a component %1 that does not exist (the components are %2).").arg(a(0), a(1));
        break;
    case MessageId::ParameterNotWhole: text = tr("“%1” must be a whole number.").arg(label(0)); break;
    case MessageId::ParameterOutOfRange: text = tr("“%1” must be from %2 to %3.").arg(label(0), a(1), a(2)); break;
    case MessageId::ParameterNotANumber: text = tr("“%1” must be a number.").arg(label(0)); break;
    case MessageId::ParameterNotAPair: text = tr("“%1” must be a pair of numbers x, y.").arg(label(0)); break;
    case MessageId::ParameterNotFinite:
        text = a(1).isEmpty() ? tr("“%1” must be a finite number.").arg(label(0))
                              : tr("“%1” must be a finite number ≥ 0.").arg(label(0));
        break;
    case MessageId::ParameterTooLarge: text = tr("“%1” must be at most 1e15 in magnitude.").arg(label(0)); break;
    case MessageId::SidesTooFew: text = tr("A body needs at least 3 sides (a polygon), not %1.").arg(a(0)); break;
    case MessageId::SidesTooMany: text = tr("A body has at most %2 sides, not %1.").arg(a(0), a(1)); break;
    case MessageId::FrameTooSmall: text = tr("The frame must be at least 1 × 1 px."); break;
    case MessageId::TooManyVertices:
        text = tr("Bodies × sides must be at most %1 vertices in all: lower the bodies or the sides.").arg(a(0));
        break;
    case MessageId::BezierOutlineTooCostly:
        text = tr("A Bézier outline of degree %1 sampled at %2 points costs %3 interpolations, more than %4: lower the "
                  "sides or the Bézier samples.")
                   .arg(a(0), a(1), a(2), a(3));
        break;
    case MessageId::BodiesDoNotFit:
        text = tr("%1 bodies of radius %2 px do not fit side by side in a %3 × %4 px frame, and piled up their %5 vertices "
                  "would all touch (at most %6 may start piled): lower the bodies, the sides or the radius, or widen the "
                  "frame.")
                   .arg(a(0), a(1), a(2), a(3), a(4), a(5));
        break;
    case MessageId::StableKnobOutOfRange:
        text = tr("The stable solver takes substeps from %1 to %2, an edge compliance from 0 to %3 and a damping ratio "
                  "from 0 to %4.")
                   .arg(StableSettings::kMinSubsteps)
                   .arg(StableSettings::kMaxSubsteps)
                   .arg(displayNumber(StableSettings::kMaxEdgeCompliance), displayNumber(StableSettings::kMaxEdgeDampingRatio));
        break;
    case MessageId::BSplineDegreeOutOfRange:
        text = tr("The degree of a B-spline must be from 1 to %2, not %1.").arg(a(0), a(1));
        break;
    case MessageId::BSplineTooFewPoints:
        text = tr("A B-spline of degree %1 needs at least %2 control points, not %3.").arg(a(0), a(1), a(2));
        break;
    case MessageId::BSplineKnotCount:
        text = tr("A B-spline of degree %1 with %2 control points needs %3 knots, not %4.").arg(a(0), a(1), a(2), a(3));
        break;
    case MessageId::BSplineWeightCount:
        text = tr("A rational B-spline needs one weight per control point: %1 weights, not %2.").arg(a(0), a(1));
        break;
    case MessageId::BSplineNotFinite: text = tr("%1 is not a finite number.").arg(a(0)); break;
    case MessageId::BSplineKnotsDecrease:
        text = tr("The knots must not decrease: u_%1 = %2 is greater than u_%3 = %4.").arg(a(0), a(1), a(2), a(3));
        break;
    case MessageId::BSplineInteriorMultiplicity:
        text = tr("The knot %1 is repeated %2 times; inside, a B-spline of degree %3 allows it at most %4 times.")
                   .arg(a(0), a(1), a(2), a(3));
        break;
    case MessageId::BSplineEndMultiplicity:
        text = tr("The knot %1 is repeated %2 times; at an end, a B-spline of degree %3 allows it at most %4 times.")
                   .arg(a(0), a(1), a(2), a(3));
        break;
    case MessageId::BSplineEmptyDomain: text = tr("The domain [%1, %2] of the B-spline is empty.").arg(a(0), a(1)); break;
    case MessageId::BSplineWeightNotPositive: text = tr("The weight w_%1 = %2 must be positive.").arg(a(0), a(1)); break;
    case MessageId::KnotInsertionTimes: text = tr("A knot is inserted at least once, not %1 times.").arg(a(0)); break;
    case MessageId::KnotOutsideDomain: text = tr("The knot %1 is outside the domain [%2, %3].").arg(a(0), a(1), a(2)); break;
    case MessageId::KnotInsertionMultiplicity:
        text = tr("The knot %1 already has multiplicity %2: inserting it %3 more times would exceed the degree %4.")
                   .arg(a(0), a(1), a(2), a(3));
        break;
    case MessageId::BSplineCannotUnclamp:
        text = tr("This rational B-spline cannot float its ends: every choice of outer knots tried needs a weight that "
                  "is not positive.");
        break;
    case MessageId::None:
        if (currentLanguage() == QLatin1String("en"))
            return QString::fromStdString(error.message); // the core's own English says most
        switch (error.code) {
        case ErrorCode::TooFewPoints: text = tr("There are too few points."); break;
        case ErrorCode::OutOfRange: text = tr("A value is outside the range Granota accepts."); break;
        case ErrorCode::NotAFile: text = tr("The path is not a file."); break;
        case ErrorCode::CutOff: text = tr("The text is cut off before its end."); break;
        case ErrorCode::SystemRefused: text = tr("The system refused to read or write the file."); break;
        default: text = tr("A value is not written in a form Granota reads."); break;
        }
        break;
    }
    if (error.line > 0)
        return tr("Line %1: %2").arg(displayNumber(static_cast<double>(error.line)), text);
    return text;
}

} // namespace granota::ui
