#include "core/io/worked_examples.h"

#include <cassert>

namespace granota {

namespace {

Rational rationalOf(const Json& v)
{
    if (auto d = v.asNumber())
        return exactRational(*d);
    if (auto s = v.asString())
        if (auto q = parseRational(*s))
            return *q;
    assert(false && "chapter2.json holds numbers or fractions");
    return Rational(0);
}

WorkedExample parseExample(const Json& e)
{
    WorkedExample ex;
    ex.data = e;
    ex.id = e.find("id")->asString().value_or("");
    ex.tab = e.find("tab")->asString().value_or("");
    ex.kind = e.find("kind")->asString().value_or("");
    if (const Json* points = e.find("points"))
        for (const Json& p : *points->asArray())
            ex.points.emplace_back(rationalOf((*p.asArray())[0]), rationalOf((*p.asArray())[1]));
    if (const Json* degree = e.find("degree"))
        ex.degree = static_cast<int>(degree->asNumber().value_or(-1));
    if (const Json* param = e.find("param"))
        ex.parametrization = param->asString().value_or("");
    if (const Json* taus = e.find("taus"))
        for (const Json& t : *taus->asArray())
            ex.taus.push_back(rationalOf(t));
    if (const Json* tau = e.find("tau"))
        ex.taus.push_back(rationalOf(*tau));
    if (const Json* modes = e.find("modes"))
        for (const Json& m : *modes->asArray())
            ex.modes.push_back(m.asString().value_or(""));
    if (const Json* note = e.find("note"))
        ex.note = note->asString().value_or("");
    if (const Json* printed = e.find("t_as_printed"))
        for (const Json& t : *printed->asArray()) {
            RadicalSum sum;
            for (const Json& term : *t.asArray())
                sum += RadicalSum(SimplifiedSquareRoot{
                    rationalOf((*term.asArray())[0]), mpz_class(static_cast<long>((*term.asArray())[1].asNumber().value_or(1)))});
            ex.printedParameters.push_back(sum);
        }
    return ex;
}

} // namespace

const std::vector<WorkedExample>& workedExamples()
{
    static const std::vector<WorkedExample> examples = [] {
        std::vector<WorkedExample> out;
        auto json = Json::parse(workedExamplesFile());
        assert(json.ok());
        for (const Json& e : *json->find("examples")->asArray())
            out.push_back(parseExample(e));
        return out;
    }();
    return examples;
}

const WorkedExample* findWorkedExample(std::string_view id)
{
    for (const auto& ex : workedExamples())
        if (ex.id == id)
            return &ex;
    return nullptr;
}

} // namespace granota
