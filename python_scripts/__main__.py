from mortarcontact.cli import main

raise SystemExit(main())
