/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "dcpRBFKeyword.H"
#include "IStringStream.H"
#include "DynamicList.H"
#include "error.H"

#include <cmath>
#include <map>
#include <sstream>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Above this a bound is no bound
constexpr double unbounded = 1e15;

//- A number as the reference writes it: whole numbers without a point
Foam::string number(const double x)
{
    std::ostringstream os;
    if (std::abs(x) < unbounded && x == std::floor(x))
    {
        os << static_cast<long long>(x);
    }
    else
    {
        os << x;
    }
    return os.str();
}

//- A factor as the reference writes it: 1e-9, 1e9 (no exponent's sign or
//  leading zeros)
Foam::string factor(const double x)
{
    std::ostringstream os;
    os << x;
    std::string s(os.str());
    const std::size_t e = s.find('e');
    if (e != std::string::npos)
    {
        const bool negative = s[e + 1] == '-';
        std::size_t digits = e + 2;
        while (digits + 1 < s.size() && s[digits] == '0') ++digits;
        s = s.substr(0, e + 1) + (negative ? "-" : "") + s.substr(digits);
    }
    return s;
}

//- The words registered for choices without words in the table, by
//  dictionary and keyword (made at its first use: the registrations are
//  static data of other files)
std::map<std::string, std::function<Foam::wordList()>>& registered()
{
    static std::map<std::string, std::function<Foam::wordList()>> r;
    return r;
}

std::string registryKey(const char* dictionary, const char* name)
{
    return std::string(dictionary) + '/' + name;
}

Foam::string code(const Foam::string& s)
{
    return "`" + s + "`";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dcpRBFKeyword Foam::dcpRBFKeyword::choice
(
    const char* dictionary, const char* name, const char* deflt,
    const char* choices, const char* help
)
{
    return
    {
        dictionary, name, valueType::choice, 0, deflt, choices, 0, 0, true,
        true, help, scope::always, nullptr, nullptr, nullptr, nullptr
    };
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::choice
(
    const char* dictionary, const char* name, const char* deflt,
    const char* help
)
{
    return choice(dictionary, name, deflt, nullptr, help);
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::onOff
(
    const char* dictionary, const char* name, const bool deflt,
    const char* help
)
{
    return
    {
        dictionary, name, valueType::switchValue, double(deflt), nullptr,
        nullptr, 0, 1, true, true, help, scope::always, nullptr, nullptr, nullptr,
        nullptr
    };
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::real
(
    const char* dictionary, const char* name, const double deflt,
    const double lo, const bool lowIncluded,
    const double hi, const bool highIncluded, const char* help
)
{
    return
    {
        dictionary, name, valueType::real, deflt, nullptr, nullptr, lo, hi,
        lowIncluded, highIncluded, help, scope::always, nullptr, nullptr,
        nullptr, nullptr
    };
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::integer
(
    const char* dictionary, const char* name, const double deflt,
    const double lo, const double hi, const char* help
)
{
    return
    {
        dictionary, name, valueType::integer, deflt, nullptr, nullptr, lo, hi,
        true, true, help, scope::always, nullptr, nullptr, nullptr, nullptr
    };
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::length
(
    const char* dictionary, const char* name, const double lo,
    const double hi, const char* defaultText, const char* condition,
    const char* advice, const char* help
)
{
    return
    {
        dictionary, name, valueType::length, 0, nullptr, nullptr, lo, hi,
        true, true, help, scope::always, defaultText, condition, nullptr,
        advice
    };
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::other
(
    const char* dictionary, const char* name, const valueType type,
    const char* defaultText, const char* condition, const char* help
)
{
    return
    {
        dictionary, name, type, 0, nullptr, nullptr, 0, 0, true, true, help,
        scope::always, defaultText, condition, nullptr, nullptr
    };
}


Foam::dcpRBFKeyword::choicesFrom::choicesFrom
(
    const char* dictionary,
    const char* name,
    const std::function<wordList()>& words
)
{
    registered()[registryKey(dictionary, name)] = words;
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::only(const scope s) const
{
    dcpRBFKeyword k(*this);
    k.allowedWith = s;
    return k;
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::ofRule(const char* r) const
{
    dcpRBFKeyword k(only(scope::dynamic));
    k.rule = r;
    return k;
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::defaultIs(const char* text) const
{
    dcpRBFKeyword k(*this);
    k.defaultText = text;
    return k;
}


Foam::dcpRBFKeyword Foam::dcpRBFKeyword::alsoNeeds(const char* text) const
{
    dcpRBFKeyword k(*this);
    k.condition = text;
    return k;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::dcpRBFKeyword::choiceList() const
{
    if (!choices)
    {
        const auto words = registered().find(registryKey(dictionary, name));
        if (words == registered().end())
        {
            FatalErrorInFunction
                << "Keyword " << name << " of " << dictionary << ": no words"
                << " registered for its choices (dcpRBFKeyword::choicesFrom)"
                << abort(FatalError);
        }
        return words->second();
    }
    IStringStream is(choices);
    DynamicList<word> words;
    while (is.good())
    {
        word w;
        is >> w;
        if (!w.empty()) words.append(w);
    }
    return wordList(words);
}


bool Foam::dcpRBFKeyword::bounded() const
{
    return hi < unbounded;
}


bool Foam::dcpRBFKeyword::within(const double x) const
{
    const bool aboveLo = x > lo || (lowIncluded && x == lo);
    const bool belowHi = x < hi || (highIncluded && x == hi);
    return aboveLo && belowHi;
}


Foam::string Foam::dcpRBFKeyword::rangeText() const
{
    return
        string(lowIncluded ? "[" : "(") + number(lo) + ", "
      + (bounded() ? number(hi) : string("inf")) + (highIncluded ? "]" : ")");
}


Foam::string Foam::dcpRBFKeyword::typeText() const
{
    switch (type)
    {
        case valueType::patches:
            return "list of patch names, regular expressions or groups";
        case valueType::length: return "scalar [m], or `factor movingExtent`";
        case valueType::choice: return "word";
        case valueType::switchValue: return "switch";
        case valueType::real: return "scalar";
        case valueType::integer: return "integer";
        case valueType::position: return "point `(x y z)`";
        case valueType::direction: return "vector `(x y z)`";
        case valueType::name: return "word";
        case valueType::subDict: return "sub-dictionary";
    }
    return "";
}


Foam::string Foam::dcpRBFKeyword::defaultValueText() const
{
    if (defaultText)
    {
        return defaultText;
    }
    switch (type)
    {
        case valueType::choice: return code(defaultWord);
        case valueType::switchValue: return code(deflt ? "true" : "false");
        case valueType::real:
        case valueType::integer: return code(number(deflt));
        default: return "required";
    }
}


Foam::string Foam::dcpRBFKeyword::allowedText() const
{
    string text;
    switch (type)
    {
        case valueType::choice:
        {
            for (const word& w : choiceList())
            {
                text += (text.empty() ? "" : ", ") + code(w);
            }
            break;
        }
        case valueType::switchValue:
            text = "`true`, `false`";
            break;
        case valueType::length:
            text =
                "> 0, from " + factor(lo) + " to " + factor(hi)
              + " times the mesh's bounding-box diagonal";
            break;
        case valueType::real:
        case valueType::integer:
        {
            if (!bounded())
            {
                text = lowIncluded
                    ? number(lo) + " or more" : "greater than " + number(lo);
            }
            else if (lowIncluded && highIncluded)
            {
                text = number(lo) + " to " + number(hi);
            }
            else
            {
                text =
                    (lowIncluded ? "at least " : "greater than ") + number(lo)
                  + (highIncluded ? ", at most " : " and less than ")
                  + number(hi);
            }
            break;
        }
        default:
            break;
    }
    if (condition)
    {
        text += (text.empty() ? "" : "; ") + string(condition);
    }
    return text;
}


// ************************************************************************* //
