/*---------------------------------------------------------------------------*\
  dcpRBF tests
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    Each keyword is defined once (dcpRBFKeywords): the keyword reference
    docs/keywords.md has a row for every keyword of the table, in the
    section of its dictionary, whose type, default and allowed values are
    the table's; and no row of those sections that the table does not have.
    Needs DCPRBF_DIR (the repository; Alltest sets it).

\*---------------------------------------------------------------------------*/

#include "dcpRBFKeywords.H"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

using namespace Foam;

namespace
{

//- A row's cells, trimmed, without the outer bars
std::vector<std::string> cells(const std::string& row)
{
    std::vector<std::string> out;
    std::string cell;
    bool inCode = false;
    for (std::size_t i = 1; i < row.size(); ++i)
    {
        const char c = row[i];
        if (c == '`') inCode = !inCode;
        if (c == '|' && !inCode)
        {
            const auto a = cell.find_first_not_of(' ');
            const auto b = cell.find_last_not_of(' ');
            out.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
            cell.clear();
        }
        else
        {
            cell += c;
        }
    }
    return out;
}

//- The section a heading opens: the dictionary of the table (empty for
//  other headings)
std::string sectionOf(const std::string& line)
{
    static const std::map<std::string, std::string> headings
    {
        {"## `dcpRBFCoeffs`", "dcpRBFCoeffs"},
        {"## `controlPoints`", "controlPoints"},
        {"## `rotation`", "rotation"},
        {"### `bodies` entries", "bodies"},
        {"## `dcpRBFFvMeshCoeffs`", "dcpRBFFvMeshCoeffs"}
    };
    const auto it = headings.find(line);
    return it == headings.end() ? std::string() : it->second;
}

//- The rows of docs/keywords.md by section and keyword
std::map<std::string, std::map<std::string, std::vector<std::string>>> docRows()
{
    std::map<std::string, std::map<std::string, std::vector<std::string>>> rows;
    const char* dir = std::getenv("DCPRBF_DIR");
    std::ifstream is(std::string(dir ? dir : ".") + "/docs/keywords.md");
    std::string line, section;
    while (std::getline(is, line))
    {
        if (line.rfind("#", 0) == 0)
        {
            section = sectionOf(line);
        }
        else if (!section.empty() && line.rfind("| `", 0) == 0)
        {
            const std::vector<std::string> c(cells(line));
            if (c.size() >= 4)
            {
                rows[section][c[0].substr(1, c[0].size() - 2)] = c;
            }
        }
    }
    return rows;
}

} // End anonymous namespace


TEST(Keywords, EveryKeywordDocumentedAsTheTableSays)
{
    ASSERT_TRUE(std::getenv("DCPRBF_DIR")) << "DCPRBF_DIR unset";
    const auto rows = docRows();
    ASSERT_FALSE(rows.empty()) << "no keyword tables in docs/keywords.md";
    for (const dcpRBFKeyword& k : dcpRBFKeywords::all())
    {
        SCOPED_TRACE(std::string(k.dictionary) + " " + k.name);
        const auto section = rows.find(k.dictionary);
        ASSERT_NE(section, rows.end()) << "no section for " << k.dictionary;
        const auto row = section->second.find(k.name);
        ASSERT_NE(row, section->second.end())
            << "docs/keywords.md lacks the row" << nl
            << "| `" << k.name << "` | " << k.typeText().c_str() << " | "
            << k.defaultValueText().c_str() << " | " << k.allowedText().c_str()
            << " | " << k.help << " |";
        const std::vector<std::string> expected
        {
            k.typeText(), k.defaultValueText(), k.allowedText()
        };
        const std::vector<std::string> documented
        (
            row->second.begin() + 1, row->second.begin() + 4
        );
        EXPECT_EQ(documented, expected)
            << "docs/keywords.md's row should begin" << nl
            << "| `" << k.name << "` | " << expected[0].c_str() << " | "
            << expected[1].c_str() << " | " << expected[2].c_str() << " |";
    }
}


TEST(Keywords, NoDocumentedKeywordOutsideTheTable)
{
    for (const auto& section : docRows())
    {
        const wordList known(dcpRBFKeywords::names(section.first));
        for (const auto& row : section.second)
        {
            EXPECT_TRUE(known.found(row.first))
                << section.first << ": " << row.first
                << " is documented but not read";
        }
    }
}


TEST(Keywords, ChoicesAndBoundsAreConsistent)
{
    for (const dcpRBFKeyword& k : dcpRBFKeywords::all())
    {
        SCOPED_TRACE(std::string(k.dictionary) + " " + k.name);
        if (k.type == dcpRBFKeyword::valueType::choice)
        {
            EXPECT_TRUE(k.choiceList().found(k.defaultWord));
        }
        if
        (
            k.type == dcpRBFKeyword::valueType::real
         || k.type == dcpRBFKeyword::valueType::integer
        )
        {
            EXPECT_LT(k.lo, k.hi);
            if (!k.defaultText)
            {
                EXPECT_TRUE(k.within(k.deflt)) << "default " << k.deflt;
            }
        }
    }
}
