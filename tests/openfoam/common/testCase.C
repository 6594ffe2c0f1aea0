/*---------------------------------------------------------------------------*\
  dcpRBF tests
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
\*---------------------------------------------------------------------------*/

#include "testCase.H"
#include "OFstream.H"
#include "OSspecific.H"

#include <cstdlib>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::dcpRBFTest::testCase::write
(
    const fileName& rel,
    const word& cls,
    const string& body
) const
{
    mkDir((dir_/rel).path());
    OFstream os(dir_/rel);
    os  << "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class "
        << cls.c_str() << ";\n    object " << rel.name().c_str() << ";\n}\n"
        << body.c_str() << nl;
}


Foam::dcpRBFTest::testCase::testCase
(
    label dim,
    label n,
    const string& coeffs,
    const word& frontBack,
    const string& bottomBC,
    const string& grading
)
{
    char tmpl[] = "/tmp/dcpRBFTest-XXXXXX";
    dir_ = ::mkdtemp(tmpl);

    const scalar zMax = dim == 2 ? 0.1 : 1.0;
    const label nz = dim == 2 ? 1 : n;
    const word frontType(dim == 2 ? "empty" : frontBack);
    OStringStream bm;
    bm  << "convertToMeters 1;\nvertices ("
        << "(0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 " << zMax << ") (1 0 " << zMax
        << ") (1 1 " << zMax << ") (0 1 " << zMax << "));\n"
        << "blocks (hex (0 1 2 3 4 5 6 7) (" << n << ' ' << n << ' ' << nz
        << ") simpleGrading " << grading.c_str() << ");\nedges ();\nboundary (\n"
        << " left { type patch; faces ((0 4 7 3)); }\n"
        << " right { type patch; faces ((1 2 6 5)); }\n"
        << " bottom { type wall; faces ((0 1 5 4)); }\n"
        << " top { type wall; faces ((3 7 6 2)); }\n"
        << " front { type " << frontType << "; faces ((0 3 2 1)); }\n"
        << " back { type " << frontType << "; faces ((4 5 6 7)); }\n);\n";
    write("system/blockMeshDict", "dictionary", bm.str());
    write
    (
        "system/controlDict", "dictionary",
        "application moveDynamicMesh; startFrom startTime; startTime 0;"
        " stopAt endTime; endTime 1; deltaT 1; writeControl timeStep;"
        " writeInterval 1; writeFormat ascii; writePrecision 17;"
        " timeFormat general; timePrecision 6; runTimeModifiable false;"
    );
    write
    (
        "system/fvSchemes", "dictionary",
        "ddtSchemes {} gradSchemes {} divSchemes {} laplacianSchemes {}"
        " interpolationSchemes {} snGradSchemes {}"
    );
    write("system/fvSolution", "dictionary", "");
    write
    (
        "constant/dynamicMeshDict", "dictionary",
        "dynamicFvMesh dynamicMotionSolverFvMesh;\nmotionSolver dcpRBF;\n"
        "dcpRBFCoeffs\n{\n" + coeffs + "\n}\n"
    );
    const string frontBC
    (
        dim == 2 ? "{ type empty; }"
      : frontBack == "wall" ? "{ type fixedValue; value uniform (0 0 0); }"
      : "{ type " + frontBack + "; }"
    );
    write
    (
        "0/pointDisplacement", "pointVectorField",
        "dimensions [0 1 0 0 0 0 0];\ninternalField uniform (0 0 0);\n"
        "boundaryField\n{\n"
        "    \"(left|right|top)\" { type fixedValue; value uniform (0 0 0); }\n"
        "    bottom " + bottomBC + "\n"
        "    \"(front|back)\" " + frontBC + "\n}\n"
    );

    const string cmd("blockMesh -case " + dir_ + " > " + dir_ + "/log.blockMesh 2>&1");
    if (std::system(cmd.c_str()) != 0)
    {
        FatalErrorInFunction
            << "blockMesh failed in " << dir_ << exit(FatalError);
    }

    runTime_.reset
    (
        new Time(Time::controlDictName, fileName(dir_.path()), fileName(dir_.name()))
    );
    mesh_.reset
    (
        new fvMesh
        (
            IOobject
            (
                fvMesh::defaultRegion,
                runTime_->timeName(),
                *runTime_,
                IOobject::MUST_READ
            )
        )
    );
}


Foam::dcpRBFTest::testCase::~testCase()
{
    mesh_.clear();
    runTime_.clear();
    if (!std::getenv("DCPRBF_KEEP_TEST_CASES"))
    {
        rmDir(dir_);
    }
}


Foam::IOdictionary Foam::dcpRBFTest::testCase::dynamicMeshDict() const
{
    return IOdictionary
    (
        IOobject
        (
            "dynamicMeshDict",
            runTime_->constant(),
            *mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
}


// ************************************************************************* //
