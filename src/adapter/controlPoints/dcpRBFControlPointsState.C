/*---------------------------------------------------------------------------*\
  dcpRBF: radial-basis-function mesh motion with dynamic control points
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBFControlPoints, continued: the restart state (what the set was
    selected with, the set, the trials' schedule, the blend), written and
    read back.
\*---------------------------------------------------------------------------*/

#include "dcpRBFControlPoints.H"
#include "Time.H"
#include "dcpRBFVersion.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::dcpRBFControlPoints::selectedWith
(
    const dcpRBFContext& context,
    const label nCandidates
)
{
    const polyMesh& mesh = context.mesh();
    const dcpRBFSettings& settings = context.settings();
    const auto names = [&](const labelList& ids)
    {
        wordList sorted(ids.size());
        forAll(ids, i)
        {
            sorted[i] = mesh.boundaryMesh()[ids[i]].name();
        }
        Foam::sort(sorted);
        string s;
        for (const word& name : sorted)
        {
            s += (s.empty() ? "" : " ") + name;
        }
        return "(" + s + ")";
    };
    dictionary d;
    // as strings: written quoted, read back as written
    const auto put = [&](const word& key, const std::string& value)
    {
        d.set(key, string(value));
    };
    put("movingPatches", names(settings.movingPatchIDs()));
    put("staticPatches", names(settings.staticPatchIDs()));
    put("boundaryPoints", Foam::name(nCandidates));
    put("function", settings.kernel().name());
    put("supportRadius", Foam::name(settings.kernel().radius()));
    put("polynomial", Switch(settings.polynomial()).c_str());
    // (not for the whole mesh: the states written before regions match)
    if (!context.region().whole())
    {
        put("region", context.region().source());
    }
    settings.selection().setDependsOn(d);
    return d;
}


Foam::string Foam::dcpRBFControlPoints::changedSettings() const
{
    const dictionary* was = state_.findDict("selectedWith");
    string changes;
    const auto add = [&](const string& what)
    {
        changes += (changes.empty() ? "" : ", ") + what;
    };
    if (!was)
    {
        // a state written before the settings were kept: the boundary's
        // size alone can be checked
        for (const label i : state_.get<labelList>("indices"))
        {
            if (i < 0 || i >= boundary_.size())
            {
                add
                (
                    "the boundary points (a control point's index " + Foam::name(i)
                  + " beyond this run's " + Foam::name(boundary_.size()) + ")"
                );
                break;
            }
        }
        return changes;
    }
    for (const entry& e : selectedWith_)
    {
        const word& key = e.keyword();
        const string now(selectedWith_.get<string>(key));
        const string before(was->getOrDefault<string>(key, "(none)"));
        if (now != before)
        {
            add(key + " " + before + " -> " + now);
        }
    }
    for (const entry& e : *was)
    {
        if (!selectedWith_.found(e.keyword()))
        {
            add(e.keyword() + " " + was->get<string>(e.keyword()) + " -> (none)");
        }
    }
    return changes;
}


void Foam::dcpRBFControlPoints::storeState(dictionary& state) const
{
    state.set("selectedWith", selectedWith_);
    state.set("ready", ready_);
    state.set("indices", dcpRBFCompat::makeList<label>(set_.indices()));
    state.set("ages", dcpRBFCompat::makeList<label>(set_.ages()));
}


bool Foam::dcpRBFControlPoints::readState()
{
    if (!state_.found("indices"))
    {
        // (selection all: the set is every candidate, nothing is lost)
        if
        (
            state_.time().value() != 0
         && !settings_.selection().everyCandidate()
        )
        {
            WarningInFunction
                << "No control-point state " << state_.objectPath() << ": the"
                << " control set is selected anew at the first step with"
                << " motion and the swap rule's state starts over. If this run continues one that moved the mesh, it"
                << " does not continue it exactly: restart from a time written"
                << " with its uniform/dcpRBFState (decomposePar and"
                << " reconstructPar carry it with the time's uniform folder)"
                << endl;
        }
        return false;
    }
    if (!state_.get<bool>("ready"))
    {
        return false;
    }
    const string changes(changedSettings());
    if (!changes.empty())
    {
        WarningInFunction
            << "The restart state " << state_.objectPath() << " was selected"
            << " with other settings: " << changes.c_str() << "." << nl
            << "    The control set is selected anew (at the first step with"
            << " motion, as at the start of a run) and the swap rule's"
            << " state starts over: the run does not continue"
            << " the one that wrote the state exactly. To continue it"
            << " exactly, restart with the settings it was written with."
            << endl;
        return false;
    }
    const labelList indices(state_.get<labelList>("indices"));
    const labelList ages(state_.get<labelList>("ages"));
    set_.reset(std::vector<Eigen::Index>(indices.begin(), indices.end()));
    set_.setAges(std::vector<int>(ages.begin(), ages.end()));
    Info<< "dcpRBF: restarting with " << set_.size() << " control points from "
        << state_.objectPath() << endl;
    return true;
}


// ************************************************************************* //
