#include "apcs/formats/sif_path.h"

#include "apcs/animation/input_limits.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"

#include <expat.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <type_traits>

namespace apcs {

namespace {

static_assert(std::is_same_v<XML_Char, char>, "expat must hand over UTF-8 strings (Debian's: no XML_UNICODE)");

// Synfig's tolerance for two times to be one (synfig-core time.h, Time::epsilon_): 0.0005 s.
constexpr double synfig_time_epsilon_seconds = 0.0005;
// The frame rate of a canvas without an fps attribute (Synfig's RendDesc default).
constexpr double default_fps = 24.0;
// A coordinate's text longer than this is no number Synfig writes (it writes ten decimals).
constexpr std::size_t longest_number_text = 256;
// The first piece of the text handed to expat; later pieces are at least as long as what expat
// holds unfinished (SifReader::feed).
constexpr std::size_t first_piece_bytes = 64 * 1024;

// The interpolations Synfig writes in a waypoint's before and after. "auto" is TCB, Synfig's
// Kochanek-Bartels spline: the only one APCS's path is.
constexpr std::array<std::string_view, 7> interpolation_names{"auto",  "clamped", "constant", "ease",
                                                              "halt",  "linear",  "manual"};
constexpr std::uint8_t tcb_interpolation = 0;

// One waypoint as read, before the waypoints are sorted by time.
struct SifWaypoint {
    double frame = 0; // its time in frames of the canvas
    double u = 0;     // the vector (u, v), in Synfig units
    double v = 0;
    double tension = 0;
    double continuity = 0;
    double bias = 0;
    int line = 0;
    std::uint8_t before = tcb_interpolation; // indices into interpolation_names
    std::uint8_t after = tcb_interpolation;
};

constexpr bool is_xml_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && is_xml_blank(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && is_xml_blank(text.back()))
        text.remove_suffix(1);
    return text;
}

// What a message shows of a value from the document: quote_field's first 24 characters, control
// and non-ASCII bytes as \xNN, without its quotes.
std::string shown(std::string_view value)
{
    const std::string quoted = quote_field(value);
    return quoted.substr(1, quoted.size() - 2);
}

std::string attribute_text(std::string_view name, std::string_view value)
{
    return std::string(name) + "=\"" + shown(value) + "\"";
}

std::string element_text(std::string_view name) { return "<" + shown(name) + ">"; }

const char* attribute(const XML_Char** attributes, std::string_view name)
{
    for (const XML_Char** pair = attributes; *pair != nullptr; pair += 2)
        if (name == pair[0])
            return pair[1];
    return nullptr;
}

// The frames one of Synfig's time units stands for at `fps`, or nothing for another letter.
std::optional<double> frames_per_unit(char unit, double fps)
{
    switch (ascii_lower(unit)) {
    case 'h': return 3600.0 * fps;
    case 'm': return 60.0 * fps;
    case 's': return fps;
    case 'f': return 1.0;
    default: return std::nullopt;
    }
}

std::size_t number_end(std::string_view text, std::size_t start)
{
    const auto in_number = [](char c) {
        return (c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-' || c == 'e' || c == 'E';
    };
    while (start < text.size() && in_number(text[start]))
        ++start;
    return start;
}

// A waypoint's time in frames at `fps`, or why it cannot be read.
struct FrameTime {
    double frames = 0;
    std::string problem; // empty when read
};

constexpr std::string_view time_form =
    "expected NUMBER UNIT pairs with units h, m, s, f (\"12f\", \"0.5s\", \"1s 12f\")";

// Synfig's Time syntax (synfig-core time.cpp), as its documents write it: NUMBER UNIT pairs with
// units h, m, s and f, blanks between; a last number without a unit counts frames, as Synfig
// counts it. SOT, EOT and the hh:mm:ss form are refused: no waypoint of a path is written so.
FrameTime frames_of(std::string_view text, double fps)
{
    // The message is made only for a time at fault: a path may have a million waypoints.
    const auto refused = [original = text](std::string_view why) {
        return FrameTime{0, attribute_text("time", original) + std::string(why)};
    };
    text = trimmed(text);
    if (equals_ignoring_case(text, "SOT") || equals_ignoring_case(text, "BOT") || equals_ignoring_case(text, "EOT"))
        return refused(" is the start or end of all time, which APCS cannot space; " + std::string(time_form));
    if (text.find(':') != std::string_view::npos)
        return refused(" is in the hh:mm:ss form, which APCS does not read; " + std::string(time_form));
    if (text.empty())
        return refused(" is empty; " + std::string(time_form));
    double frames = 0;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t end = number_end(text, at);
        const std::optional<double> amount = parse_number(text.substr(at, end - at));
        if (!amount || !std::isfinite(*amount) || std::abs(*amount) > max_dat_magnitude)
            return refused(" is not a time APCS reads; " + std::string(time_form) +
                           ", each number finite and within 1e9");
        if (end == text.size())
            return {frames + *amount, {}};
        const std::optional<double> unit = frames_per_unit(text[end], fps);
        if (!unit)
            return refused(" has the unknown unit " + quote_field(text.substr(end, 1)) + "; " + std::string(time_form));
        frames += *amount * *unit;
        at = end + 1;
        while (at < text.size() && is_xml_blank(text[at]))
            ++at;
    }
    return {frames, {}};
}

Vec3 in_plane(double u, double v, SifPlane plane)
{
    switch (plane) {
    case SifPlane::top: break;
    case SifPlane::front: return {0, u, v};
    case SifPlane::side: return {u, 0, v};
    }
    return {u, v, 0};
}

std::string plural(std::size_t count, std::string_view noun)
{
    return std::to_string(count) + " " + std::string(noun) + (count == 1 ? "" : "s");
}

// Reads a Synfig document's text through expat, keeping only the chosen parameter's waypoints.
// Each element's place is one byte on a stack; the first problem stops expat and is the answer.
class SifReader {
public:
    SifReader(const std::string& file_name, const SifReading& reading);

    Expected<SifPath> read(std::string_view text);

private:
    // Where an open element stands, as far as the path is concerned.
    enum class Node : std::uint8_t {
        root_canvas,
        inner_canvas,         // a group's inline canvas, an exported canvas: its layers are not read
        root_layer,           // a layer of the root canvas
        inner_layer,
        wanted_param,         // <param name="PARAM"> of a root layer
        inner_wanted_param,   // the same in a layer of an inner canvas
        path,                 // the chosen <animated type="vector">
        waypoint,
        vector,
        x,
        y,
        ignored,
    };

    static void XMLCALL on_start(void* reader, const XML_Char* name, const XML_Char** attributes);
    static void XMLCALL on_end(void* reader, const XML_Char* name);
    static void XMLCALL on_text(void* reader, const XML_Char* text, int length);
    static void XMLCALL on_entity(void* reader, const XML_Char* name, int is_parameter_entity, const XML_Char* value,
                                  int value_length, const XML_Char* base, const XML_Char* system_id,
                                  const XML_Char* public_id, const XML_Char* notation);
    static void XMLCALL on_attribute_list(void* reader, const XML_Char* element, const XML_Char* attribute,
                                          const XML_Char* type, const XML_Char* default_value, int required);
    static void XMLCALL on_skipped_entity(void* reader, const XML_Char* name, int is_parameter_entity);

    Expected<void> feed(std::string_view text);
    Node place_of(const char* name, const XML_Char** attributes);
    Node start_root(const char* name, const XML_Char** attributes);
    Node start_layer(Node canvas);
    Node start_in_layer(Node layer, const char* name, const XML_Char** attributes);
    Node start_param_value(Node param, const char* name, const XML_Char** attributes);
    Node start_animated(Node param, const XML_Char** attributes);
    Node start_waypoint(const char* name, const XML_Char** attributes);
    bool read_waypoint_attributes(const XML_Char** attributes);
    std::optional<double> staff_attribute(const XML_Char** attributes, std::string_view name);
    std::optional<std::uint8_t> interpolation_attribute(const XML_Char** attributes, std::string_view name);
    Node start_waypoint_value(const char* name, const XML_Char** attributes);
    Node start_coordinate(const char* name);
    void end(Node closed);
    void end_coordinate(Node closed);
    void end_vector();
    void end_waypoint();
    void end_path();
    bool enter_element();
    void note_not_literal(std::string what);

    Expected<SifPath> finish();
    std::string absence_details() const;
    Expected<void> check_times(const std::vector<SifWaypoint>& sorted) const;
    Expected<void> check_interpolations(const std::vector<SifWaypoint>& sorted) const;
    std::optional<std::string> spacing_warning(const std::vector<SifWaypoint>& sorted) const;
    std::optional<std::string> temporal_tension_warning() const;

    int line() const
    {
        return static_cast<int>(std::min<XML_Size>(XML_GetCurrentLineNumber(m_parser.get()), INT_MAX));
    }
    std::string param_text() const { return "`" + m_reading.param + "`"; }
    // Keeps the first problem and stops expat (which may still call back: every handler looks first).
    void refuse(std::string message, int at_line);
    void refuse(std::string message) { refuse(std::move(message), line()); }

    const std::string& m_file_name;
    const SifReading& m_reading;
    std::unique_ptr<XML_ParserStruct, decltype(&XML_ParserFree)> m_parser;
    std::optional<Diagnostic> m_problem;
    std::vector<Node> m_open;
    std::size_t m_depth = 0; // elements open, counted after the path too
    double m_fps = default_fps;

    // What was seen before the path, for the message when there is none.
    std::size_t m_root_layers = 0;
    std::size_t m_static_params = 0;
    std::optional<std::pair<int, std::string>> m_first_not_literal; // line, what it is

    // The path: its <animated>'s line, its waypoints, the one being read.
    int m_path_line = 0;
    bool m_path_read = false;
    std::vector<SifWaypoint> m_waypoints;
    SifWaypoint m_waypoint;
    bool m_has_value = false;
    int m_vector_line = 0;
    bool m_has_x = false;
    bool m_has_y = false;
    std::string m_number_text;
    int m_number_line = 0;
    std::size_t m_temporal_tensions = 0;
    std::pair<int, std::string> m_first_temporal_tension;
};

SifReader::SifReader(const std::string& file_name, const SifReading& reading)
    : m_file_name(file_name)
    , m_reading(reading)
    , m_parser(XML_ParserCreate(nullptr), &XML_ParserFree)
{
}

void SifReader::refuse(std::string message, int at_line)
{
    if (!m_problem)
        m_problem = Diagnostic{m_file_name, at_line, std::move(message)};
    XML_StopParser(m_parser.get(), XML_FALSE);
}

Expected<SifPath> SifReader::read(std::string_view text)
{
    if (!m_parser)
        return Diagnostic{m_file_name, 0, "expat could not start (out of memory)"};
    XML_Parser parser = m_parser.get();
    XML_SetUserData(parser, this);
    XML_SetElementHandler(parser, &on_start, &on_end);
    XML_SetCharacterDataHandler(parser, &on_text);
    // A Synfig document declares no entities: any declaration is refused as it is met, before
    // anything could be expanded (billion laughs) or loaded (external entities; expat loads
    // nothing anyway without an external entity handler, which is never set).
    XML_SetEntityDeclHandler(parser, &on_entity);
    XML_SetAttlistDeclHandler(parser, &on_attribute_list);
    XML_SetSkippedEntityHandler(parser, &on_skipped_entity);
    XML_SetParamEntityParsing(parser, XML_PARAM_ENTITY_PARSING_NEVER);
    if (auto fed = feed(text); !fed)
        return fed.error();
    return finish();
}

// The text in pieces: the first of first_piece_bytes, each later one at least as long as what
// expat holds unfinished. Expat (2.5) scans an unfinished token again from its start with each
// piece, so equal pieces would make a long token (a megabyte-long attribute) cost its length
// squared; pieces that grow with it keep the whole reading linear in the text's length, and the
// memory expat holds within the longest token plus a piece.
Expected<void> SifReader::feed(std::string_view text)
{
    std::size_t piece = first_piece_bytes;
    std::size_t fed = 0;
    do {
        const std::size_t size = std::min({piece, text.size() - fed, static_cast<std::size_t>(INT_MAX)});
        const bool last = fed + size == text.size();
        const XML_Status status =
            XML_Parse(m_parser.get(), text.data() + fed, static_cast<int>(size), last ? XML_TRUE : XML_FALSE);
        if (m_problem)
            return *m_problem;
        if (status != XML_STATUS_OK)
            return Diagnostic{m_file_name, line(),
                              std::string("not a Synfig document: ") +
                                  XML_ErrorString(XML_GetErrorCode(m_parser.get()))};
        fed += size;
        // Outside a handler, expat's current byte index is where its unfinished token starts.
        const XML_Index unfinished_from = XML_GetCurrentByteIndex(m_parser.get());
        const std::size_t unfinished =
            unfinished_from < 0 ? 0 : fed - std::min(fed, static_cast<std::size_t>(unfinished_from));
        piece = std::max(first_piece_bytes, unfinished);
    } while (fed < text.size());
    return ok;
}

void XMLCALL SifReader::on_start(void* reader, const XML_Char* name, const XML_Char** attributes)
{
    auto& self = *static_cast<SifReader*>(reader);
    if (self.m_problem || !self.enter_element())
        return;
    if (self.m_path_read)
        return;
    self.m_open.push_back(self.place_of(name, attributes));
}

void XMLCALL SifReader::on_end(void* reader, const XML_Char*)
{
    auto& self = *static_cast<SifReader*>(reader);
    if (self.m_depth > 0)
        --self.m_depth;
    if (self.m_problem || self.m_path_read || self.m_open.empty())
        return;
    const Node closed = self.m_open.back();
    self.m_open.pop_back();
    self.end(closed);
}

void XMLCALL SifReader::on_text(void* reader, const XML_Char* text, int length)
{
    auto& self = *static_cast<SifReader*>(reader);
    if (self.m_problem || self.m_open.empty() || (self.m_open.back() != Node::x && self.m_open.back() != Node::y))
        return;
    const std::size_t size = static_cast<std::size_t>(length);
    if (self.m_number_text.size() + size > longest_number_text)
        return self.refuse("the number in " + std::string(self.m_open.back() == Node::x ? "<x>" : "<y>") +
                               " is longer than " + std::to_string(longest_number_text) + " characters",
                           self.m_number_line);
    self.m_number_text.append(text, size);
}

void XMLCALL SifReader::on_entity(void* reader, const XML_Char* name, int is_parameter_entity, const XML_Char*, int,
                                  const XML_Char*, const XML_Char*, const XML_Char*, const XML_Char*)
{
    auto& self = *static_cast<SifReader*>(reader);
    const std::string entity =
        is_parameter_entity ? "the parameter entity %" + shown(name) : "the entity " + shown(name);
    self.refuse("declares " + entity + "; a Synfig document declares none, and APCS expands none");
}

// A DTD's default attributes would be added to the elements read (a waypoint's before, say).
void XMLCALL SifReader::on_attribute_list(void* reader, const XML_Char* element, const XML_Char*, const XML_Char*,
                                          const XML_Char*, int)
{
    auto& self = *static_cast<SifReader*>(reader);
    self.refuse("declares attributes of " + element_text(element) +
                "; a Synfig document declares none, and APCS takes none from a DTD");
}

// A reference to an entity declared in an external DTD, which expat does not read.
void XMLCALL SifReader::on_skipped_entity(void* reader, const XML_Char* name, int)
{
    auto& self = *static_cast<SifReader*>(reader);
    self.refuse("refers to the entity " + shown(name) + ", which APCS does not expand; a Synfig document uses none");
}

SifReader::Node SifReader::place_of(const char* name, const XML_Char** attributes)
{
    if (m_open.empty())
        return start_root(name, attributes);
    const std::string_view element = name;
    switch (const Node parent = m_open.back()) {
    case Node::root_canvas:
    case Node::inner_canvas:
        if (element == "layer")
            return start_layer(parent);
        break;
    case Node::root_layer:
    case Node::inner_layer: return start_in_layer(parent, name, attributes);
    case Node::wanted_param:
    case Node::inner_wanted_param: return start_param_value(parent, name, attributes);
    case Node::path: return start_waypoint(name, attributes);
    case Node::waypoint: return start_waypoint_value(name, attributes);
    case Node::vector: return start_coordinate(name);
    case Node::x:
    case Node::y:
        refuse("expected a number in " + std::string(parent == Node::x ? "<x>" : "<y>") + ", found the element " +
               element_text(element));
        return Node::ignored;
    case Node::ignored: break;
    }
    return element == "canvas" ? Node::inner_canvas : Node::ignored;
}

SifReader::Node SifReader::start_root(const char* name, const XML_Char** attributes)
{
    if (std::string_view(name) != "canvas") {
        refuse("not a Synfig document: the root element is " + element_text(name) + ", expected <canvas>");
        return Node::ignored;
    }
    if (const char* fps = attribute(attributes, "fps")) {
        const std::optional<double> rate = parse_number(trimmed(fps));
        if (!rate || !std::isfinite(*rate) || *rate <= 0 || *rate > max_dat_magnitude)
            refuse(attribute_text("fps", fps) + " is not a frame rate; expected a number above 0 and within 1e9");
        else
            m_fps = *rate;
    }
    return Node::root_canvas;
}

SifReader::Node SifReader::start_layer(Node canvas)
{
    if (canvas == Node::inner_canvas)
        return Node::inner_layer;
    ++m_root_layers;
    return Node::root_layer;
}

SifReader::Node SifReader::start_in_layer(Node layer, const char* name, const XML_Char** attributes)
{
    const std::string_view element = name;
    if (element == "canvas")
        return Node::inner_canvas;
    const char* param = attribute(attributes, "name");
    if (element != "param" || param == nullptr || param != m_reading.param)
        return Node::ignored;
    if (const char* use = attribute(attributes, "use")) {
        note_not_literal("linked to the exported value " + attribute_text("use", use));
        return Node::ignored;
    }
    return layer == Node::root_layer ? Node::wanted_param : Node::inner_wanted_param;
}

SifReader::Node SifReader::start_param_value(Node param, const char* name, const XML_Char** attributes)
{
    const std::string_view element = name;
    if (element == "animated")
        return start_animated(param, attributes);
    if (element == "vector") {
        ++m_static_params;
        return Node::ignored;
    }
    note_not_literal(element_text(element) + ", a converted value");
    return element == "canvas" ? Node::inner_canvas : Node::ignored;
}

void SifReader::note_not_literal(std::string what)
{
    if (!m_first_not_literal)
        m_first_not_literal = {line(), std::move(what)};
}

SifReader::Node SifReader::start_animated(Node param, const XML_Char** attributes)
{
    const char* type = attribute(attributes, "type");
    if (type == nullptr || std::string_view(type) != "vector") {
        refuse(param_text() + " is animated as type " + (type ? "\"" + shown(type) + "\"" : std::string("(none)")) +
               ", not as a vector; APCS reads an animated vector (<animated type=\"vector\">)");
        return Node::ignored;
    }
    if (param == Node::inner_wanted_param) {
        refuse(param_text() + " is animated in a layer of a nested canvas (a group's or an exported one); APCS reads "
                              "the layers of the root canvas only, since a parent layer's transformation would move "
                              "the path");
        return Node::ignored;
    }
    if (const char* use = attribute(attributes, "use")) {
        refuse("the animated " + param_text() + " is linked (" + attribute_text("use", use) +
               "); APCS reads waypoints written in the document only");
        return Node::ignored;
    }
    m_path_line = line();
    return Node::path;
}

SifReader::Node SifReader::start_waypoint(const char* name, const XML_Char** attributes)
{
    if (std::string_view(name) != "waypoint") {
        refuse("expected <waypoint> in the animated " + param_text() + ", found " + element_text(name));
        return Node::ignored;
    }
    if (m_waypoints.size() == max_dat_points) {
        refuse("more than " + std::to_string(max_dat_points) + " waypoints; a path has at most that many");
        return Node::ignored;
    }
    if (const char* use = attribute(attributes, "use")) {
        refuse("the waypoint's value is linked (" + attribute_text("use", use) +
               "), not a literal <vector>; APCS reads waypoints with their own values only");
        return Node::ignored;
    }
    m_waypoint = SifWaypoint{};
    m_waypoint.line = line();
    m_has_value = false;
    return read_waypoint_attributes(attributes) ? Node::waypoint : Node::ignored;
}

bool SifReader::read_waypoint_attributes(const XML_Char** attributes)
{
    const char* time = attribute(attributes, "time");
    if (time == nullptr) {
        refuse("a <waypoint> without a time; expected time=\"12f\" or the like");
        return false;
    }
    const FrameTime frame = frames_of(time, m_fps);
    if (!frame.problem.empty()) {
        refuse(frame.problem);
        return false;
    }
    m_waypoint.frame = frame.frames;
    for (auto [name, value] : {std::pair{"tension", &m_waypoint.tension},
                               std::pair{"continuity", &m_waypoint.continuity}, std::pair{"bias", &m_waypoint.bias}}) {
        const std::optional<double> read = staff_attribute(attributes, name);
        if (!read)
            return false;
        *value = *read;
    }
    for (auto [name, value] : {std::pair{"before", &m_waypoint.before}, std::pair{"after", &m_waypoint.after}}) {
        const std::optional<std::uint8_t> read = interpolation_attribute(attributes, name);
        if (!read)
            return false;
        *value = *read;
    }
    // Temporal tension shapes the timing between waypoints, not the path: read, then only noted.
    const char* temporal = attribute(attributes, "temporal-tension");
    const std::optional<double> temporal_tension = temporal ? parse_number(trimmed(temporal)) : 0.0;
    if (!temporal_tension || !std::isfinite(*temporal_tension)) {
        refuse("expected a finite number in " + attribute_text("temporal-tension", temporal));
        return false;
    }
    if (*temporal_tension != 0 && m_temporal_tensions++ == 0)
        m_first_temporal_tension = {m_waypoint.line, attribute_text("temporal-tension", temporal)};
    return true;
}

// Tension, continuity or bias: absent is 0, as Synfig reads it; else a number in [-1, 1].
std::optional<double> SifReader::staff_attribute(const XML_Char** attributes, std::string_view name)
{
    const char* text = attribute(attributes, name);
    if (text == nullptr)
        return 0.0;
    const std::optional<double> value = parse_number(trimmed(text));
    if (value && std::isfinite(*value) && limits::staff_value.contains(*value))
        return value;
    if (!value)
        refuse("expected a number in " + attribute_text(name, text));
    else if (!std::isfinite(*value))
        refuse("expected a finite number in " + attribute_text(name, text));
    else
        refuse(attribute_text(name, text) + " is outside " + range_text(limits::staff_value));
    return std::nullopt;
}

// Before or after: absent is TCB, as Synfig reads it (synfig-core waypoint.cpp).
std::optional<std::uint8_t> SifReader::interpolation_attribute(const XML_Char** attributes, std::string_view name)
{
    const char* text = attribute(attributes, name);
    if (text == nullptr)
        return tcb_interpolation;
    const auto known = std::find(interpolation_names.begin(), interpolation_names.end(), std::string_view(text));
    if (known != interpolation_names.end())
        return static_cast<std::uint8_t>(known - interpolation_names.begin());
    refuse(attribute_text(name, text) +
           " is no interpolation Synfig writes (auto, clamped, constant, ease, halt, linear, manual)");
    return std::nullopt;
}

SifReader::Node SifReader::start_waypoint_value(const char* name, const XML_Char** attributes)
{
    const std::string_view element = name;
    if (m_has_value) {
        refuse("a second value in the waypoint, " + element_text(element) + "; expected one <vector>");
        return Node::ignored;
    }
    m_has_value = true;
    const char* use = attribute(attributes, "use");
    if (element != "vector" || use != nullptr) {
        const std::string what =
            use ? "linked (" + attribute_text("use", use) + ")" : element_text(element) + " (a converted value)";
        refuse("the waypoint's value is " + what + ", not a literal <vector>; APCS reads waypoints with their own "
                                                   "values only");
        return Node::ignored;
    }
    m_vector_line = line();
    m_has_x = false;
    m_has_y = false;
    return Node::vector;
}

SifReader::Node SifReader::start_coordinate(const char* name)
{
    const std::string_view element = name;
    if (element != "x" && element != "y") {
        refuse("expected <x> or <y> in the vector, found " + element_text(element));
        return Node::ignored;
    }
    bool& seen = element == "x" ? m_has_x : m_has_y;
    if (seen) {
        refuse("a second " + element_text(element) + " in the vector");
        return Node::ignored;
    }
    seen = true;
    m_number_text.clear();
    m_number_line = line();
    return element == "x" ? Node::x : Node::y;
}

void SifReader::end(Node closed)
{
    switch (closed) {
    case Node::x:
    case Node::y: return end_coordinate(closed);
    case Node::vector: return end_vector();
    case Node::waypoint: return end_waypoint();
    case Node::path: return end_path();
    default: return;
    }
}

void SifReader::end_coordinate(Node closed)
{
    const std::string element = closed == Node::x ? "<x>" : "<y>";
    const std::string_view text = trimmed(m_number_text);
    const std::optional<double> value = parse_number(text);
    if (!value)
        return refuse("expected a number in " + element + ", found " + quote_field(text), m_number_line);
    if (!std::isfinite(*value))
        return refuse("expected a finite number in " + element + ", found " + quote_field(text), m_number_line);
    if (std::abs(*value) > max_dat_magnitude)
        return refuse("number " + quote_field(text) + " in " + element + " is out of range; expected |value| <= 1e9",
                      m_number_line);
    (closed == Node::x ? m_waypoint.u : m_waypoint.v) = *value;
}

void SifReader::end_vector()
{
    if (!m_has_x || !m_has_y)
        refuse(std::string("the vector has no ") + (m_has_x ? "<y>" : "<x>") + "; expected <x> and <y>", m_vector_line);
}

void SifReader::end_waypoint()
{
    if (!m_has_value)
        return refuse("the waypoint has no value; expected a <vector>", m_waypoint.line);
    m_waypoints.push_back(m_waypoint);
}

// The path is read: nothing after it matters, so expat goes on only to check the text is XML
// (and the elements' depth, which holds expat's memory).
void SifReader::end_path()
{
    m_path_read = true;
    XML_SetCharacterDataHandler(m_parser.get(), nullptr);
}

// Expat keeps every open element's name: a document of elements nested without end would take
// memory in proportion to its size, so depth is bounded far above a Synfig document's few dozen.
bool SifReader::enter_element()
{
    if (++m_depth <= most_nested_elements)
        return true;
    refuse("elements nested more than " + std::to_string(most_nested_elements) +
           " deep; a Synfig document nests a few dozen");
    return false;
}

Expected<SifPath> SifReader::finish()
{
    if (!m_path_read)
        return Diagnostic{m_file_name, 0,
                          "no layer has an animated vector " + param_text() + " (" + absence_details() +
                              "); apcs path --sif-param names another parameter"};
    if (m_waypoints.size() < 2)
        return Diagnostic{m_file_name, m_path_line,
                          "the animated " + param_text() + " has " + plural(m_waypoints.size(), "waypoint") +
                              "; a path needs at least 2"};
    // Synfig keeps a value's waypoints in time order, whatever the document's order.
    std::vector<SifWaypoint> sorted = std::move(m_waypoints);
    std::sort(sorted.begin(), sorted.end(), [](const SifWaypoint& a, const SifWaypoint& b) {
        return a.frame != b.frame ? a.frame < b.frame : a.line < b.line;
    });
    if (auto times = check_times(sorted); !times)
        return times.error();
    if (auto interpolations = check_interpolations(sorted); !interpolations)
        return interpolations.error();
    SifPath path;
    if (auto warning = spacing_warning(sorted))
        path.warnings.push_back(std::move(*warning));
    if (auto warning = temporal_tension_warning())
        path.warnings.push_back(std::move(*warning));
    DatPart part{"", Closure::open, {}};
    part.points.reserve(sorted.size());
    for (const SifWaypoint& waypoint : sorted)
        part.points.push_back({in_plane(waypoint.u, waypoint.v, m_reading.plane),
                               StaffValues{waypoint.tension, waypoint.continuity, waypoint.bias, 0.0}, waypoint.line});
    path.file.parts.push_back(std::move(part));
    return path;
}

std::string SifReader::absence_details() const
{
    std::string details = "the root canvas has " + plural(m_root_layers, "layer");
    if (m_static_params > 0)
        details += ", " + std::to_string(m_static_params) + " with a static " + param_text();
    if (m_first_not_literal)
        details += "; at line " + std::to_string(m_first_not_literal->first) + " " + param_text() + " is " +
                   m_first_not_literal->second + ", which APCS does not read";
    return details;
}

std::string frame_text(double frame) { return significant_number(frame, 9); }

Expected<void> SifReader::check_times(const std::vector<SifWaypoint>& sorted) const
{
    const double same_time = synfig_time_epsilon_seconds * m_fps;
    for (std::size_t i = 1; i < sorted.size(); ++i) {
        if (sorted[i].frame - sorted[i - 1].frame >= same_time)
            continue;
        const auto [first, second] = std::minmax(sorted[i - 1].line, sorted[i].line);
        return Diagnostic{m_file_name, second,
                          "a second waypoint at frame " + frame_text(sorted[i].frame) + " (the first is at line " +
                              std::to_string(first) + "); a path passes each time once"};
    }
    return ok;
}

// Between the first and the last waypoint every interpolation must be TCB; the first waypoint's
// before and the last one's after shape nothing of the path.
Expected<void> SifReader::check_interpolations(const std::vector<SifWaypoint>& sorted) const
{
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        const SifWaypoint& waypoint = sorted[i];
        const bool before_counts = i > 0 && waypoint.before != tcb_interpolation;
        const bool after_counts = i + 1 < sorted.size() && waypoint.after != tcb_interpolation;
        if (!before_counts && !after_counts)
            continue;
        const std::string found = before_counts ? attribute_text("before", interpolation_names[waypoint.before])
                                                : attribute_text("after", interpolation_names[waypoint.after]);
        return Diagnostic{m_file_name, waypoint.line,
                          "interpolation " + found + "; APCS reads TCB waypoints only (auto)"};
    }
    return ok;
}

// APCS spaces control points equally in time; Synfig, at their times. Names the first span that
// differs from the first one, and the frames around it.
std::optional<std::string> SifReader::spacing_warning(const std::vector<SifWaypoint>& sorted) const
{
    const double tolerance = synfig_time_epsilon_seconds * m_fps;
    const double first_span = sorted[1].frame - sorted[0].frame;
    std::size_t differing = 1;
    while (differing + 1 < sorted.size() &&
           std::abs((sorted[differing + 1].frame - sorted[differing].frame) - first_span) <= tolerance)
        ++differing;
    if (differing + 1 == sorted.size())
        return std::nullopt;
    // Frames 0, 1, differing, differing + 1 (every one for a short path), "…" for those left out.
    constexpr std::size_t listed_whole = 6;
    std::string frames;
    std::size_t previous = 0;
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        const bool listed = sorted.size() <= listed_whole || i <= 1 || i == differing || i == differing + 1;
        if (!listed)
            continue;
        frames += (i == 0 ? "" : i == previous + 1 ? ", " : ", …, ") + frame_text(sorted[i].frame);
        previous = i;
    }
    if (previous + 1 < sorted.size())
        frames += ", …";
    return Diagnostic{m_file_name, sorted[differing + 1].line,
                      "the waypoints are not equally spaced in time (frames " + frames +
                          "); APCS spaces them equally, so the curve differs from Synfig's"}
        .to_string();
}

std::optional<std::string> SifReader::temporal_tension_warning() const
{
    if (m_temporal_tensions == 0)
        return std::nullopt;
    const std::string others =
        m_temporal_tensions == 1 ? "" : " (and " + plural(m_temporal_tensions - 1, "more waypoint") + ")";
    return Diagnostic{m_file_name, m_first_temporal_tension.first,
                      m_first_temporal_tension.second + others +
                          ": APCS ignores temporal tension, so the path's timing differs from Synfig's"}
        .to_string();
}

} // namespace

Expected<SifPath> parse_sif_path(std::string_view text, const std::string& file_name, const SifReading& reading)
{
    return SifReader(file_name, reading).read(text);
}

bool is_sif_name(std::string_view name)
{
    constexpr std::string_view extension = ".sif";
    if (name.size() < extension.size())
        return false;
    const std::string_view tail = name.substr(name.size() - extension.size());
    return std::equal(tail.begin(), tail.end(), extension.begin(), [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) == b;
    });
}

SifPlane sif_plane_of(double theta_degrees, double phi_degrees)
{
    const auto same = [](double a, double b) { return std::fmod(a - b, 360.0) == 0.0; };
    if (same(theta_degrees, 0.0) && same(phi_degrees, 90.0))
        return SifPlane::front;
    if (same(theta_degrees, -90.0) && same(phi_degrees, 90.0))
        return SifPlane::side;
    return SifPlane::top;
}

} // namespace apcs
