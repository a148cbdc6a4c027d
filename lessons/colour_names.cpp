#include "colour_names.h"

#include <algorithm>

namespace forcelab::lessons {

namespace {

// Okabe & Ito (2008) where a colour of theirs reads as its name; red,
// purple, grey and white are this list's own (their distances to the others
// are checked by tests/test_lesson_colours.cpp). Red and grey are the colours
// the lessons always used for them, so a lesson that writes "#e05050" for
// its red ball is drawn red as before.
constexpr std::array<ColourName, 11> kNames{{
    {{"sky blue", "light blue", {}}, 0x56b4e9},
    {{"blue", {}, {}}, 0x0072b2},
    {{"red", {}, {}}, 0xe05050},
    {{"orange", {}, {}}, 0xe69f00},
    {{"yellow", {}, {}}, 0xf0e442},
    {{"green", {}, {}}, 0x009e73},
    {{"purple", "violet", {}}, 0x8e44ad},
    {{"pink", {}, {}}, 0xcc79a7},
    {{"black", {}, {}}, 0x000000},
    {{"grey", "gray", {}}, 0x808080},
    {{"white", {}, {}}, 0xf0f0f0},
}};

} // namespace

std::span<const ColourName> colourNames()
{
    return kNames;
}

std::optional<sim::Rgb> colourOfName(const QString& name)
{
    // "Sky  Blue" is "sky blue": case and runs of spaces do not matter.
    const QByteArray key = name.simplified().toLower().toUtf8();
    const std::string_view k(key.constData(), static_cast<std::size_t>(key.size()));
    for (const ColourName& c : kNames)
        for (std::string_view w : c.words)
            if (!w.empty() && w == k)
                return c.color;
    return std::nullopt;
}

QString nameOfColour(sim::Rgb color)
{
    for (const ColourName& c : kNames)
        if (c.color == (color & 0xffffffu))
            return QString::fromUtf8(c.words[0].data(), static_cast<qsizetype>(c.words[0].size()));
    return {};
}

bool isListedColour(sim::Rgb color)
{
    return std::any_of(kNames.begin(), kNames.end(), [&](const ColourName& c) { return c.color == (color & 0xffffffu); });
}

QStringList colourWords()
{
    QStringList words;
    for (const ColourName& c : kNames)
        for (std::string_view w : c.words)
            if (!w.empty())
                words << QString::fromUtf8(w.data(), static_cast<qsizetype>(w.size()));
    return words; // the list's order: "sky blue" before "blue"
}

} // namespace forcelab::lessons
