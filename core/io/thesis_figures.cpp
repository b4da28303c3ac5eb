#include "core/io/thesis_figures.h"

#include <cassert>

namespace granota {

namespace {

std::string text(const Json& object, const char* key)
{
    const Json* v = object.find(key);
    return v ? v->asString().value_or("") : std::string();
}

CaptionText captionOf(const Json* v)
{
    if (!v)
        return {};
    return {text(*v, "ca"), text(*v, "en")};
}

FigureVariant parseVariant(const Json& v)
{
    FigureVariant variant;
    variant.name = text(v, "name");
    if (const Json* state = v.find("state"))
        variant.state = *state;
    if (const Json* events = v.find("events"))
        variant.events = *events;
    variant.note = captionOf(v.find("note"));
    return variant;
}

ThesisFigure parseFigure(const Json& f)
{
    ThesisFigure figure;
    figure.number = text(f, "number");
    figure.tab = text(f, "tab");
    figure.example = text(f, "example");
    figure.scene = text(f, "scene");
    figure.art = text(f, "art");
    if (const Json* steps = f.find("steps"))
        figure.steps = static_cast<long>(steps->asNumber().value_or(0));
    figure.caption = captionOf(f.find("caption"));
    if (const Json* state = f.find("state"))
        figure.state = *state;
    if (const Json* variants = f.find("variants"))
        for (const Json& v : *variants->asArray())
            figure.variants.push_back(parseVariant(v));
    if (figure.variants.empty()) // one way to draw it: the figure as the thesis prints it
        figure.variants.push_back(FigureVariant{"definition", Json::Object{}, Json::Array{}, {}});
    return figure;
}

} // namespace

const std::vector<ThesisFigure>& thesisFigures()
{
    static const std::vector<ThesisFigure> figures = [] {
        std::vector<ThesisFigure> out;
        auto json = Json::parse(thesisFiguresFile());
        assert(json.ok());
        for (const Json& f : *json->find("figures")->asArray())
            out.push_back(parseFigure(f));
        return out;
    }();
    return figures;
}

const ThesisFigure* findThesisFigure(std::string_view number)
{
    for (const ThesisFigure& f : thesisFigures())
        if (f.number == number)
            return &f;
    return nullptr;
}

const FigureVariant* findFigureVariant(const ThesisFigure& figure, std::string_view name)
{
    if (name.empty())
        return &figure.variants.front();
    for (const FigureVariant& v : figure.variants)
        if (v.name == name)
            return &v;
    return nullptr;
}

std::string figureVariantNames(const ThesisFigure& figure)
{
    std::string names;
    for (const FigureVariant& v : figure.variants)
        names += (names.empty() ? "" : ", ") + v.name;
    return names;
}

} // namespace granota
