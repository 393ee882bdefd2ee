// The same checks in Unity's Test Runner (Window > General > Test Runner, Play Mode or Edit Mode):
// each [Test] method of Hedge.Tests becomes one NUnit test case, named Class.Method as the Mono
// runner (Program.cs) names it, so the sources of this folder run unchanged in both. Compiled only
// in Unity with tests enabled (UNITY_INCLUDE_TESTS, the asmdef's define constraint); under Mono this
// file is empty.
//
// The checks that read the repository's data/ folder (the spot meshes, tests/cases/refusals.txt),
// which the package does not ship, are reported as ignored unless HEDGE_DATA_DIR names that folder.
// The library version is checked against this package's package.json.
#if UNITY_INCLUDE_TESTS
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Text.RegularExpressions;

namespace Hedge.Tests
{
    public sealed class UnityTestRunner
    {
        /// <summary>Every [Test] method of this assembly, class by class in name order.</summary>
        public static IEnumerable<NUnit.Framework.TestCaseData> Checks()
        {
            const BindingFlags all = BindingFlags.Static | BindingFlags.Public | BindingFlags.NonPublic;
            foreach (Type type in typeof(UnityTestRunner).Assembly.GetTypes().OrderBy(t => t.FullName, StringComparer.Ordinal))
                foreach (MethodInfo method in type.GetMethods(all).OrderBy(m => m.MetadataToken))
                    if (method.IsDefined(typeof(TestAttribute), false))
                        yield return new NUnit.Framework.TestCaseData(method).SetName(type.Name + "." + method.Name);
        }

        [NUnit.Framework.OneTimeSetUp]
        public void SetUpContext()
        {
            string data = Environment.GetEnvironmentVariable("HEDGE_DATA_DIR");
            Context.DataDir = string.IsNullOrEmpty(data) ? Path.Combine(UnityEngine.Application.temporaryCachePath, "no-data")
                                                         : data;
            Context.ScratchDir = Path.Combine(UnityEngine.Application.temporaryCachePath, "hedge-tests");
            Directory.CreateDirectory(Context.ScratchDir);
            Context.ExpectedVersion = PackageVersion();
        }

        [NUnit.Framework.TestCaseSource("Checks")]
        public void Run(MethodInfo check)
        {
            try
            {
                check.Invoke(null, null);
            }
            catch (TargetInvocationException e)
            {
                Exception inner = e.InnerException;
                // A file of the data folder that is not there: a .NET exception, or the library's (HedgeException,
                // Io) naming the file.
                bool missingData = inner is FileNotFoundException || inner is DirectoryNotFoundException ||
                                   inner.Message.Contains(Context.DataDir);
                if (missingData && !Directory.Exists(Context.DataDir))
                    NUnit.Framework.Assert.Ignore("needs the repository's data/ folder: set HEDGE_DATA_DIR (" + inner.Message + ")");
                NUnit.Framework.Assert.Fail(inner.GetType().Name + ": " + inner.Message + "\n" + inner.StackTrace);
            }
        }

        // The "version" of this package's package.json (Packages/com.hedge.halfedge/ in the editor), or the
        // library's own version where the file cannot be read (a player).
        static string PackageVersion()
        {
            string path = Path.GetFullPath("Packages/com.hedge.halfedge/package.json");
            if (File.Exists(path))
            {
                Match m = Regex.Match(File.ReadAllText(path), "\"version\"\\s*:\\s*\"([^\"]+)\"");
                if (m.Success) return m.Groups[1].Value;
            }
            return HalfEdgeMesh.LibraryVersion.ToString(3);
        }
    }
}
#endif
