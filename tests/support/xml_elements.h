#pragma once

#include <cctype>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs::test {

// An element of a parsed XML document: its name, attributes and direct text (entities decoded).
struct XmlElement {
    std::string name;
    std::map<std::string, std::string> attributes;
    std::string text;
};

// A small well-formedness check for the documents APCS writes: one root element, tags that nest
// and close, attributes quoted once each with no '<' in them, '&' only as one of the five
// predefined entities, nothing but white space or the declaration outside the root. The elements
// in document order when well-formed, else nothing.
class XmlReader {
public:
    static std::optional<std::vector<XmlElement>> read(std::string_view document)
    {
        XmlReader reader(document);
        if (!reader.parse())
            return std::nullopt;
        return reader.m_elements;
    }

private:
    explicit XmlReader(std::string_view document) : m_text(document) {}

    bool parse()
    {
        if (m_text.substr(0, 5) == "<?xml") {
            const std::size_t end = m_text.find("?>");
            if (end == std::string_view::npos)
                return false;
            m_at = end + 2;
        }
        skip_space();
        if (!element())
            return false;
        skip_space();
        return m_at == m_text.size();
    }

    bool element()
    {
        if (!take('<'))
            return false;
        const std::size_t index = m_elements.size();
        m_elements.push_back({name(), {}, {}});
        if (m_elements[index].name.empty())
            return false;
        while (true) {
            const bool spaced = skip_space();
            if (take('/'))
                return take('>');
            if (take('>'))
                break;
            const std::string attribute = name();
            if (!spaced || attribute.empty() || !take('=') || !take('"'))
                return false;
            const std::size_t end = m_text.find('"', m_at);
            if (end == std::string_view::npos)
                return false;
            const auto value = decoded(m_text.substr(m_at, end - m_at));
            if (!value || !m_elements[index].attributes.emplace(attribute, *value).second)
                return false;
            m_at = end + 1;
        }
        while (m_at < m_text.size()) {
            if (m_text.substr(m_at, 2) == "</") {
                m_at += 2;
                return name() == m_elements[index].name && take('>');
            }
            if (m_text[m_at] == '<') {
                if (!element())
                    return false;
                continue;
            }
            const std::size_t end = std::min(m_text.find('<', m_at), m_text.size());
            const auto text = decoded(m_text.substr(m_at, end - m_at));
            if (!text)
                return false;
            m_elements[index].text += *text;
            m_at = end;
        }
        return false;
    }

    static std::optional<std::string> decoded(std::string_view raw)
    {
        static const std::map<std::string_view, char> entities{
            {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
        std::string text;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] == '<')
                return std::nullopt;
            if (raw[i] != '&') {
                text += raw[i];
                continue;
            }
            const std::size_t end = raw.find(';', i);
            if (end == std::string_view::npos)
                return std::nullopt;
            const auto entity = entities.find(raw.substr(i, end - i + 1));
            if (entity == entities.end())
                return std::nullopt;
            text += entity->second;
            i = end;
        }
        return text;
    }

    std::string name()
    {
        const std::size_t start = m_at;
        while (m_at < m_text.size() && (std::isalnum(static_cast<unsigned char>(m_text[m_at])) != 0 ||
                                        m_text[m_at] == ':' || m_text[m_at] == '-' || m_text[m_at] == '_'))
            ++m_at;
        return std::string(m_text.substr(start, m_at - start));
    }

    bool take(char wanted)
    {
        if (m_at >= m_text.size() || m_text[m_at] != wanted)
            return false;
        ++m_at;
        return true;
    }

    bool skip_space()
    {
        const std::size_t start = m_at;
        while (m_at < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_at])) != 0)
            ++m_at;
        return m_at > start;
    }

    std::string_view m_text;
    std::size_t m_at = 0;
    std::vector<XmlElement> m_elements;
};

// The elements named `name`, in document order.
inline std::vector<XmlElement> elements_named(const std::vector<XmlElement>& elements, const std::string& name)
{
    std::vector<XmlElement> found;
    for (const XmlElement& element : elements)
        if (element.name == name)
            found.push_back(element);
    return found;
}

} // namespace apcs::test
