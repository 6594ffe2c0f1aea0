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
    The keyword tables of the adapter's headers (\table in their Usage)
    have a row for every keyword of their dictionary and none else, whose
    description is the table's help and whose default (and required) is
    the table's. Needs DCPRBF_DIR (the repository; Alltest sets it).

\*---------------------------------------------------------------------------*/

#include "dcpRBFKeywords.H"

#include <gtest/gtest.h>

#include <algorithm>
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

//- A text without its backticks (a header's table is not markdown)
std::string plain(std::string s)
{
    s.erase(std::remove(s.begin(), s.end(), '`'), s.end());
    return s;
}

//- A header's keyword table: its rows, each its cells by column name
//  (trimmed; the first line names the columns)
std::vector<std::map<std::string, std::string>> headerTable
(
    const std::string& header
)
{
    std::vector<std::map<std::string, std::string>> rows;
    const char* dir = std::getenv("DCPRBF_DIR");
    std::ifstream is(std::string(dir ? dir : ".") + "/" + header);
    std::string line;
    std::vector<std::string> columns;
    bool inTable = false;
    while (std::getline(is, line))
    {
        const auto a = line.find_first_not_of(' ');
        const std::string text(a == std::string::npos ? "" : line.substr(a));
        if (text == "\\table" || text == "\\endtable")
        {
            inTable = text == "\\table";
            columns.clear();
            continue;
        }
        if (!inTable || text.empty())
        {
            continue;
        }
        const std::vector<std::string> c(cells("|" + text + "|"));
        if (columns.empty())
        {
            columns = c;
            continue;
        }
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < columns.size(); ++i)
        {
            row[columns[i]] = i < c.size() ? c[i] : "";
        }
        rows.push_back(row);
    }
    return rows;
}

//- A header's row: its cells, an empty last one as a bare bar
std::string headerRow(const std::vector<std::string>& cells)
{
    std::string row;
    for (const std::string& c : cells)
    {
        row += (row.empty() ? "" : " | ") + c;
    }
    return cells.back().empty() ? row.substr(0, row.size() - 1) : row;
}

//- A header's row of keyword k as the table says it
std::string headerRow(const dcpRBFKeyword& k, const bool required)
{
    const std::string deflt(plain(k.defaultValueText()));
    std::vector<std::string> c{k.name, plain(k.help)};
    if (required)
    {
        c.push_back(deflt == "required" ? "yes" : "no");
    }
    c.push_back(deflt == "required" ? "" : deflt);
    return headerRow(c);
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


TEST(Keywords, HeaderTablesAsTheTableSays)
{
    ASSERT_TRUE(std::getenv("DCPRBF_DIR")) << "DCPRBF_DIR unset";
    const std::map<std::string, std::string> headers
    {
        {"src/adapter/settings/dcpRBFSettings.H", "dcpRBFCoeffs"},
        {"src/adapter/settings/dcpRBFSelectionSettings.H", "controlPoints"},
        {"src/adapter/rotation/dcpRBFRotation.H", "rotation"}
    };
    for (const auto& h : headers)
    {
        SCOPED_TRACE(h.first);
        const auto rows = headerTable(h.first);
        ASSERT_FALSE(rows.empty()) << "no \\table in " << h.first;
        const bool required = rows[0].count("Required");
        std::map<std::string, std::string> documented;
        for (const auto& row : rows)
        {
            const auto at = [&](const char* column)
            {
                const auto c = row.find(column);
                return c == row.end() ? std::string() : c->second;
            };
            std::vector<std::string> c{at("Property"), at("Description")};
            if (required)
            {
                c.push_back(at("Required"));
            }
            c.push_back(at("Default"));
            documented[at("Property")] = headerRow(c);
        }
        std::string expected;
        for (const dcpRBFKeyword& k : dcpRBFKeywords::all())
        {
            if (h.second == k.dictionary)
            {
                expected += "        " + headerRow(k, required) + "\n";
            }
        }
        std::string differ;
        for (const dcpRBFKeyword& k : dcpRBFKeywords::all())
        {
            const auto row = documented.find(k.name);
            if
            (
                h.second == k.dictionary
             && (row == documented.end() || row->second != headerRow(k, required))
            )
            {
                differ += (differ.empty() ? "" : " ") + std::string(k.name);
            }
        }
        EXPECT_EQ(differ, "")
            << h.first << ": the rows of " << differ.c_str() << " are not"
            << " the table's; its rows should be (dcpRBFKeywords):" << nl
            << expected.c_str();
        const wordList known(dcpRBFKeywords::names(h.second));
        for (const auto& row : documented)
        {
            EXPECT_TRUE(known.found(row.first))
                << h.first << ": " << row.first << " is in the header's table"
                << " but not a keyword of " << h.second.c_str();
        }
    }
}
