// The shared table of refused edits and bad handles (tests/cases/refusals.txt, which says its format)
// run through the C# binding: each case must give the table's status and text, as the C ABI's and the
// JS API's tests of the same table must. A refused edit returns false / an invalid handle / 0 and sets
// LastRefusal; any other failure throws a HedgeException.
using System;
using System.Collections.Generic;
using System.IO;
using System.Text;
using System.Text.RegularExpressions;

namespace Hedge.Tests
{
    public static class RefusalTableTests
    {
        // An element: e:A-B, h:A>B, or e:N, h:N, f:N.
        static int Element(HalfEdgeMesh mesh, string token)
        {
            Match pair = Regex.Match(token, @"^([eh]):(\d+)[->](\d+)$");
            if (pair.Success)
            {
                HalfEdge h = mesh.FindHalfEdge(new Vertex(int.Parse(pair.Groups[2].Value)),
                                               new Vertex(int.Parse(pair.Groups[3].Value)));
                Check.True(h.IsValid, token + ": no such half-edge");
                return pair.Groups[1].Value == "e" ? h.Edge.Index : h.Index;
            }
            return int.Parse(token.Substring(2));
        }

        struct Edit
        {
            public string Name;
            public int[] Elements;
        }

        static Edit Parse(HalfEdgeMesh mesh, string text)
        {
            string[] tokens = text.Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries);
            var elements = new int[tokens.Length - 1];
            for (int i = 1; i < tokens.Length; ++i) elements[i - 1] = Element(mesh, tokens[i]);
            return new Edit { Name = tokens[0], Elements = elements };
        }

        // True if the edit was done, false if refused; throws for any other failure.
        static bool Run(HalfEdgeMesh mesh, Edit e)
        {
            int a = e.Elements[0];
            switch (e.Name)
            {
                case "flip": return mesh.Flip(new Edge(a));
                case "collapse": return mesh.Collapse(new HalfEdge(a)).IsValid;
                case "split_edge": return mesh.SplitEdge(new Edge(a), 0, 0, 0).IsValid;
                case "split_face": return mesh.SplitFace(new Face(a), 0, 0, 0).IsValid;
                case "cut_face": return mesh.CutFace(new HalfEdge(a), new HalfEdge(e.Elements[1])).IsValid;
                case "fill_hole": return mesh.FillHole(new HalfEdge(a)) > 0;
                default: throw new ArgumentException("unknown edit " + e.Name);
            }
        }

        [Test]
        static void SharedTable()
        {
            string path = Path.Combine(Context.DataDir, "..", "tests", "cases", "refusals.txt");
            var meshes = new Dictionary<string, string>();
            int cases = 0;
            foreach (string raw in File.ReadAllLines(path))
            {
                string line = raw.Trim();
                if (line.StartsWith("mesh "))
                {
                    int at = line.IndexOf('=');
                    meshes[line.Substring(5, at - 5).Trim()] = line.Substring(at + 1).Trim().Replace(';', '\n');
                    continue;
                }
                if (!line.StartsWith("case ")) continue;
                string[] f = line.Substring(5).Split('|');
                for (int i = 0; i < f.Length; ++i) f[i] = f[i].Trim();
                string where = "case " + f[0] + " | " + f[1] + " | " + f[2];
                ++cases;
                using (HalfEdgeMesh mesh = HalfEdgeMesh.FromBytes(Encoding.UTF8.GetBytes(meshes[f[0]]), f[0] + ".obj"))
                {
                    Edit checkedEdit = Parse(mesh, f[2]);  // before the edits done first
                    if (f[1] != "-")
                        foreach (string first in f[1].Split(';'))
                            Check.True(Run(mesh, Parse(mesh, first.Trim())), where + ": the edit done first");
                    string status = "HEDGE_OK", text = "", code = "";
                    try
                    {
                        if (!Run(mesh, checkedEdit))
                        {
                            status = "HEDGE_ERROR_REFUSED";
                            text = mesh.LastRefusal;
                        }
                    }
                    catch (HedgeException e)
                    {
                        status = e.StatusName;
                        text = e.Message;
                    }
                    code = mesh.LastRefusalCode.ToString();
                    Check.Equal(f[3], status, where);
                    Check.Equal(f[4], text, where);
                    Check.Equal(RefusalCodeTests.PascalCase(f[5]), code, where);
                    Check.Valid(mesh, where);
                }
            }
            Check.True(cases >= 10, "the table's cases: " + cases);
        }
    }
}
