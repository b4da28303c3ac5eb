#include "tests/fuzz/properties.h"

#include "core/io/json.h"
#include "core/io/point_list.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational.h"
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <vector>

namespace granota::fuzz {

namespace {

/// At most this much of a text in a finding (the input itself is in the artifact).
std::string shown(std::string_view s)
{
    constexpr std::size_t kMax = 300;
    std::string out(s.substr(0, kMax));
    if (s.size() > kMax)
        out += "…";
    return "«" + out + "»";
}

/// Runs a check, turning an escaping exception into a finding (a parser of user text must
/// answer with an Error, never throw).
std::string guarded(const std::function<std::string()>& check)
{
    try {
        return check();
    } catch (const std::exception& e) {
        return std::string("exception escaped: ") + e.what();
    } catch (...) {
        return "a non-standard exception escaped";
    }
}

// ---------------------------------------------------------------- JSON

std::string firstNonFinite(const Json& v, const std::string& path)
{
    if (auto d = v.asNumber())
        return std::isfinite(*d) ? std::string() : path;
    if (const auto* a = v.asArray()) {
        for (std::size_t i = 0; i < a->size(); ++i)
            if (auto bad = firstNonFinite((*a)[i], path + "[" + std::to_string(i) + "]"); !bad.empty())
                return bad;
    } else if (const auto* o = v.asObject()) {
        for (const auto& [key, item] : *o)
            if (auto bad = firstNonFinite(item, path + "." + key); !bad.empty())
                return bad;
    }
    return {};
}

std::string jsonProperty(std::string_view input)
{
    auto first = Json::parse(input);
    if (!first)
        return first.error().message.empty() ? "a refusal without a message" : std::string();
    if (auto bad = firstNonFinite(*first, "$"); !bad.empty())
        return "a non-finite number was read at " + bad;
    const std::string dumped = first->dump();
    auto second = Json::parse(dumped);
    if (!second)
        return "dump() " + shown(dumped) + " does not parse: " + second.error().message;
    if (second->dump() != dumped)
        return "parse → dump → parse → dump changed " + shown(dumped) + " into " + shown(second->dump());
    const std::string pretty = first->dump(2);
    auto third = Json::parse(pretty);
    if (!third)
        return "dump(2) " + shown(pretty) + " does not parse: " + third.error().message;
    if (third->dump() != dumped)
        return "the pretty form " + shown(pretty) + " reads back as " + shown(third->dump()) + ", not " + shown(dumped);
    return {};
}

// ---------------------------------------------------------------- point lists

using Points = std::vector<RPoint>;

std::string text(const Points& pts)
{
    std::string out;
    for (const RPoint& p : pts)
        out += "(" + toString(p.x) + ", " + toString(p.y) + ") ";
    return shown(out);
}

std::string inlineForm(const Points& pts)
{
    std::string out;
    for (const RPoint& p : pts)
        out += (out.empty() ? "" : ";") + toString(p.x) + "," + toString(p.y);
    return out;
}

std::string csvForm(const Points& pts)
{
    std::string out = "x,y\n"; // with the header line that readers skip
    for (const RPoint& p : pts)
        out += toString(p.x) + "," + toString(p.y) + "\n";
    return out;
}

std::string jsonForm(const Points& pts)
{
    // Integers as JSON numbers, fractions as strings "p/q" (both are documented); an integer
    // beyond a double's range is a string too, since JSON numbers must fit in a double.
    const auto coordinate = [](const Rational& q) {
        return q.get_den() == 1 && std::isfinite(toDouble(q)) ? toString(q) : "\"" + toString(q) + "\"";
    };
    std::string out = "[";
    for (std::size_t i = 0; i < pts.size(); ++i)
        out += (i ? ",[" : "[") + coordinate(pts[i].x) + "," + coordinate(pts[i].y) + "]";
    return out + "]";
}

/// The doubles of the points written as the exports write them (shortest round trip).
std::string doubleCsvForm(const std::vector<Point>& pts)
{
    std::string out;
    for (const Point& p : pts)
        out += formatDouble(p.x) + "," + formatDouble(p.y) + "\n";
    return out;
}

bool sameDoubles(const std::vector<Point>& a, const std::vector<Point>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!(a[i] == b[i]))
            return false;
    return true;
}

using Reader = Expected<Points> (*)(std::string_view);

std::string pointListProperty(std::string_view input)
{
    const std::pair<const char*, Reader> readers[] = {{"parsePointList", parsePointList},
                                                      {"parsePointCsv", parsePointCsv},
                                                      {"parsePointJson", parsePointJson},
                                                      {"parsePointFile", parsePointFile}};
    for (const auto& [name, read] : readers) {
        auto points = read(input);
        if (!points) {
            if (points.error().message.empty())
                return std::string(name) + " refused without a message";
            continue;
        }
        if (points->empty())
            return std::string(name) + " accepted an empty list";
        const std::pair<std::string, Reader> forms[] = {{inlineForm(*points), parsePointList},
                                                        {csvForm(*points), parsePointCsv},
                                                        {jsonForm(*points), parsePointJson},
                                                        {csvForm(*points), parsePointFile},
                                                        {jsonForm(*points), parsePointFile}};
        for (const auto& [written, reread] : forms) {
            auto again = reread(written);
            if (!again)
                return std::string(name) + " read " + text(*points) + "; written as " + shown(written) +
                       " it is refused: " + again.error().message;
            if (*again != *points)
                return std::string(name) + " read " + text(*points) + "; written as " + shown(written) + " it reads back as " +
                       text(*again);
        }
        // As doubles (what the tabs keep): every finite one survives the shortest text.
        const std::vector<Point> doubles = toDouble(*points);
        bool finite = true;
        for (const Point& p : doubles)
            finite = finite && isFinite(p);
        if (!finite)
            continue; // too large for a double: the tabs refuse it (see the fit_import target)
        const std::string written = doubleCsvForm(doubles);
        auto again = parsePointCsv(written);
        if (!again)
            return std::string(name) + ": the doubles written as " + shown(written) + " are refused: " + again.error().message;
        if (!sameDoubles(toDouble(*again), doubles))
            return std::string(name) + ": the doubles " + shown(written) + " read back as other doubles, " +
                   shown(doubleCsvForm(toDouble(*again)));
    }
    return {};
}

// ---------------------------------------------------------------- rationals and polynomials

std::string rationalProperty(std::string_view input)
{
    auto q = parseRational(input);
    if (!q)
        return {};
    if (q->get_den() <= 0)
        return "parseRational gave a denominator ≤ 0";
    Rational canonical = *q;
    canonical.canonicalize();
    if (canonical.get_num() != q->get_num() || canonical.get_den() != q->get_den())
        return "parseRational gave a value not in lowest terms";
    const std::string written = toString(*q);
    auto again = parseRational(written);
    if (!again)
        return "toString gave " + shown(written) + ", which parseRational refuses";
    if (*again != *q)
        return "toString gave " + shown(written) + ", which reads back as " + toString(*again);
    if (toString(*again) != written)
        return "toString is not stable: " + shown(written) + " then " + shown(toString(*again));
    const double d = toDouble(*q);
    if (std::isfinite(d)) {
        // The double of what was typed, written shortest and typed again, is the same double
        // (the point table and the exports do exactly this).
        const std::string shortest = formatDouble(d);
        auto typed = parseRational(shortest);
        if (!typed)
            return "formatDouble gave " + shown(shortest) + ", which parseRational refuses";
        if (toDouble(*typed) != d)
            return "the double of " + shown(written) + " is written " + shown(shortest) + ", which reads back as " +
                   formatDouble(toDouble(*typed));
    }
    return {};
}

std::string polynomialProperty(std::string_view input)
{
    if (input.empty())
        return {};
    const char var = input.front() == 's' || input.front() == 'x' ? input.front() : 't';
    const std::string_view body = input.substr(1);
    auto p = parsePolynomial(body, var);
    if (!p)
        return {};
    const std::string written = toText(*p, std::string(1, var));
    auto again = parsePolynomial(written, var);
    if (!again)
        return "toText gave " + shown(written) + ", which parsePolynomial refuses";
    if (*again != *p)
        return "toText gave " + shown(written) + ", which reads back as " + shown(toText(*again, std::string(1, var)));
    if (toText(*again, std::string(1, var)) != written)
        return "toText is not stable: " + shown(written) + " then " + shown(toText(*again, std::string(1, var)));
    return {};
}

// ---------------------------------------------------------------- scenes

std::string nonFinite(const SceneSpec& s)
{
    std::vector<std::pair<std::string, double>> numbers;
    const FrogParams& p = s.params;
    for (const auto& [name, point] : {std::pair{"gravity", p.gravity}, std::pair{"friction", p.friction}, std::pair{"v0", p.v0},
                                      std::pair{"center", p.center}}) {
        numbers.emplace_back(std::string(name) + ".x", point.x);
        numbers.emplace_back(std::string(name) + ".y", point.y);
    }
    numbers.insert(numbers.end(), {{"area_factor", p.areaFactor},
                                   {"target_area", p.targetArea},
                                   {"spring_length", p.springLength},
                                   {"velmax", p.velmax},
                                   {"radius", p.radius},
                                   {"width", p.width},
                                   {"height", p.height},
                                   {"angle_limits.shoulder", s.chainShoulderMin},
                                   {"angle_limits.shoulder", s.chainShoulderMax},
                                   {"angle_limits.elbow", s.chainElbowMin},
                                   {"angle_limits.elbow", s.chainElbowMax}});
    for (const LegParams& l : p.legs)
        for (double v : {l.upper, l.lower, l.shoulderMin, l.shoulderMax, l.elbowMin, l.elbowMax})
            numbers.emplace_back("legs", v);
    for (double l : s.chain)
        numbers.emplace_back("chain", l);
    for (const ObstacleSpec& o : s.obstacles)
        for (const Point& q : o.points)
            numbers.insert(numbers.end(), {{"obstacles", q.x}, {"obstacles", q.y}});
    for (const ShapeSpec& sh : s.shapes) {
        for (const Point& q : sh.points)
            numbers.insert(numbers.end(), {{"shapes.points", q.x}, {"shapes.points", q.y}});
        numbers.insert(numbers.end(), {{"shapes.at", sh.at.x}, {"shapes.at", sh.at.y}});
    }
    for (const auto& [name, v] : numbers)
        if (!std::isfinite(v))
            return name + " = " + std::to_string(v);
    return {};
}

/// What every scene the core accepts must satisfy.
std::string acceptedScene(const SceneSpec& s, const std::string& how)
{
    if (auto bad = nonFinite(s); !bad.empty())
        return how + " gave a scene with a non-finite number: " + bad;
    const std::string written = sceneToJson(s).dump();
    auto json = Json::parse(written);
    if (!json)
        return how + ": sceneToJson wrote " + shown(written) + ", which does not parse: " + json.error().message;
    auto again = parseScene(*json);
    if (!again)
        return how + ": sceneToJson wrote " + shown(written) + ", which parseScene refuses: " + again.error().message;
    if (sceneToJson(*again).dump() != written)
        return how + ": sceneToJson → parseScene → sceneToJson changed " + shown(written) + " into " +
               shown(sceneToJson(*again).dump());
    // The Frog tab builds the scene on the solver the user picks: either may refuse it
    // with a message, but what it builds starts finite.
    for (SolverKind solver : {SolverKind::Seed, SolverKind::Stable}) {
        auto sim = Simulation::create(s, solver);
        if (!sim) {
            if (sim.error().message.empty())
                return how + ": the " + solverName(solver) + " solver refused the scene without a message";
            continue;
        }
        if (!(*sim)->finite())
            return how + ": the " + solverName(solver) + " solver built a scene with non-finite positions";
    }
    return {};
}

std::string sceneProperty(std::string_view input)
{
    constexpr std::string_view kSet = "\n--set ";
    const std::size_t firstSet = input.find(kSet);
    std::string_view head = input.substr(0, firstSet);
    while (!head.empty() && (head.front() == ' ' || head.front() == '\n' || head.front() == '\r' || head.front() == '\t'))
        head.remove_prefix(1);
    while (!head.empty() && (head.back() == ' ' || head.back() == '\n' || head.back() == '\r' || head.back() == '\t'))
        head.remove_suffix(1);
    Expected<SceneSpec> scene = makeError(ErrorCode::InvalidInput, "no scene");
    if (!head.empty() && head.front() == '{') {
        auto json = Json::parse(head);
        if (!json)
            return {};
        scene = parseScene(*json);
    } else {
        scene = loadScene(std::string(head));
    }
    if (!scene)
        return scene.error().message.empty() ? "a scene was refused without a message" : std::string();
    if (auto bad = acceptedScene(*scene, "the scene"); !bad.empty())
        return bad;
    std::size_t pos = firstSet;
    while (pos != std::string_view::npos) {
        pos += kSet.size();
        const std::size_t next = input.find(kSet, pos);
        std::string_view line = input.substr(pos, next == std::string_view::npos ? std::string_view::npos : next - pos);
        if (const std::size_t newline = line.find('\n'); newline != std::string_view::npos)
            line = line.substr(0, newline);
        const std::string setting(line);
        const std::string before = sceneToJson(*scene).dump();
        auto ok = applySetting(*scene, setting);
        if (!ok) {
            if (ok.error().message.empty())
                return "--set " + shown(setting) + " was refused without a message";
            if (sceneToJson(*scene).dump() != before)
                return "the refused --set " + shown(setting) + " changed the scene";
        } else if (auto bad = acceptedScene(*scene, "--set " + shown(setting)); !bad.empty()) {
            return bad;
        }
        pos = next;
    }
    return {};
}

} // namespace

std::string checkJson(std::string_view input)
{
    return guarded([&] { return jsonProperty(input); });
}
std::string checkPointList(std::string_view input)
{
    return guarded([&] { return pointListProperty(input); });
}
std::string checkRational(std::string_view input)
{
    return guarded([&] { return rationalProperty(input); });
}
std::string checkPolynomial(std::string_view input)
{
    return guarded([&] { return polynomialProperty(input); });
}
std::string checkScene(std::string_view input)
{
    return guarded([&] { return sceneProperty(input); });
}

std::string checkCore(std::string_view target, std::string_view input)
{
    if (target == "json")
        return checkJson(input);
    if (target == "point_list")
        return checkPointList(input);
    if (target == "rational")
        return checkRational(input);
    if (target == "polynomial")
        return checkPolynomial(input);
    if (target == "scene")
        return checkScene(input);
    return "no fuzz target is called '" + std::string(target) + "'";
}

void trapOnFinding(const std::string& finding, std::string_view target)
{
    if (finding.empty())
        return;
    std::fprintf(stderr, "\n==== fuzz_%.*s: property violated: %s\n", static_cast<int>(target.size()), target.data(),
                 finding.c_str());
    std::fflush(stderr);
    __builtin_trap();
}

} // namespace granota::fuzz
