/*---------------------------------------------------------------------------*\
  dcpRBF tests
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    GoogleTest main for the OpenFOAM tier: owns the argList (serial, no
    banner) and turns FatalError/FatalIOError into C++ exceptions, so a test
    can assert that bad input raises the right error.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "error.H"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char* argv[])
{
    ::testing::InitGoogleTest(&argc, argv);

    Foam::argList::noBanner();
    Foam::argList::noParallel();
    Foam::argList::noFunctionObjects();
    Foam::argList args(argc, argv, false, false, false);

    // DCPRBF_TEST_ABORT=1: let errors print and abort, to debug a test
    if (!std::getenv("DCPRBF_TEST_ABORT"))
    {
        Foam::FatalError.throwExceptions();
        Foam::FatalIOError.throwExceptions();
    }

    // The result as the exit status, whatever OpenFOAM's objects do on their
    // way out (the process otherwise exits with 0 after failed tests: the
    // mutation runner reads the status; ./Alltest the XML report)
    const int result = RUN_ALL_TESTS();
    Foam::Info<< Foam::flush;
    std::fflush(nullptr);
    std::_Exit(result);
}

// ************************************************************************* //
